/**
 * @file InputFiles.h
 * @brief Files a user names as input, checked before they are opened, and
 * their text as messages show it.
 *
 * A path may name anything: a device (`/dev/zero` reads without end), a
 * FIFO (opening it blocks until a writer comes), a folder. Every reader of
 * the toolkit asks InputFileProblem first, so that such a path is an error
 * that says what it names rather than a hang or an exhausted memory.
 */
#ifndef RiemannInputFiles_h
#define RiemannInputFiles_h

#include "RiemannCommonMetricExport.h"

#include <cstdint>
#include <limits>
#include <string>

namespace riemann
{
/**
 * "" when `path` names an existing regular file of at most `maximumBytes`,
 * else why not, as "PATH: WHAT ...", the shape of every file error here
 * ("m.json: the metric file does not exist", "/dev/zero: the metric file
 * is not a regular file (a device, FIFO or socket); give a file", "big.json:
 * the metric file has 70.0 MiB; the limit is 64.0 MiB"). Nothing is opened.
 */
RIEMANNCOMMONMETRIC_EXPORT std::string InputFileProblem(const std::string& path, const std::string& what,
  std::uint64_t maximumBytes = std::numeric_limits<std::uint64_t>::max());

/**
 * The whole file, after InputFileProblem; throws std::runtime_error with
 * its reason, or when the file cannot be read. At most `maximumBytes` are
 * read even if the file grows meanwhile.
 */
RIEMANNCOMMONMETRIC_EXPORT std::string ReadInputFile(
  const std::string& path, const std::string& what, std::uint64_t maximumBytes);
/**
 * Text read from a file as a message shows it: bytes that are not printable
 * ASCII as \xNN (a binary file's bytes must not reach the terminal), at
 * most `most` characters of the text, then "...".
 */
RIEMANNCOMMONMETRIC_EXPORT std::string PrintableFileText(const std::string& text, std::size_t most);
} // namespace riemann

#endif
