/**
 * @file RiemannVtkMessages.h
 * @brief VTK's error and warning texts as a sentence for our messages.
 *
 * vtkErrorMacro's text is "ERROR: In ./IO/XML/vtkXMLReader.cxx, line 521\n
 * vtkXMLPolyDataReader (0x5643...): Error parsing input file." (with ANSI
 * colours where the output window adds them): a source path of VTK's build
 * and an object address, which mean nothing to a user. Every place that
 * passes a VTK message on (the mesh reader, the command line, the studio's
 * jobs) passes PlainVtkMessage's form of it: "vtkXMLPolyDataReader: Error
 * parsing input file."
 */
#ifndef RiemannVtkMessages_h
#define RiemannVtkMessages_h

#include "RiemannCommonCoreModule.h" // For export macro

#include <string>

namespace riemann
{
/**
 * `message` (an ErrorEvent's or WarningEvent's text, or the output
 * window's) without its "ERROR: In FILE, line N" line, the object's address
 * and ANSI escapes, on one line: "CLASS: what it said". `className` (the
 * caller's, may be null) is used where the text names none.
 */
RIEMANNCOMMONCORE_EXPORT std::string PlainVtkMessage(
  const std::string& message, const char* className = nullptr);

/// `text` without ANSI escape sequences (ESC [ ... letter), as loguru colours VTK's log.
RIEMANNCOMMONCORE_EXPORT std::string WithoutAnsiEscapes(const std::string& text);
} // namespace riemann

#endif
