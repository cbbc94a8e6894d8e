/**
 * @file CsvColumns.h
 * @brief Reading named columns of numbers from a CSV file with a header
 * (the seeds of `riemann trace` and `riemann distance`): any column order,
 * extra columns ignored, every error naming the file and line.
 */
#ifndef RiemannCliCsvColumns_h
#define RiemannCliCsvColumns_h

#include <string>
#include <vector>

namespace riemann
{
namespace cli
{
/**
 * The rows of `path`, each the values of `names` in that order. `rows`
 * names them in messages ("seeds": "the seeds file", "no seeds after the
 * header"). Throws Failure (exit 1)
 * for a file that is not a regular file of at most 1 GiB, a header without
 * one of the names, a cell that is not a finite number, a missing cell, no
 * rows, or more than `maximumRows` rows. `lines`, when given, receives
 * each row's line number in the file (for the caller's own messages).
 */
std::vector<std::vector<double>> ReadCsvColumns(const std::string& path,
  const std::vector<std::string>& names, const std::string& rows, long long maximumRows,
  std::vector<long long>* lines = nullptr);
} // namespace cli
} // namespace riemann

#endif
