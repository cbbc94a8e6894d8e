/**
 * @file vtkRiemannReportError.h
 * @brief vtkErrorMacro that also keeps its text for the class's
 * GetLastError() (ErrorConventions.md: every filter and renderer of the
 * toolkit says its last error there, as well as through ErrorEvent).
 *
 * Usage, in a method of a vtkObject subclass with a `std::string LastError`:
 *   vtkRiemannReportErrorMacro(this->LastError, << "The image is " << w << " wide.");
 * The class clears LastError where an execution starts (RequestData).
 */
#ifndef vtkRiemannReportError_h
#define vtkRiemannReportError_h

#include "vtkSetGet.h" // For vtkErrorMacro

#include <sstream> // For the message
#include <string>  // For LastError

#define vtkRiemannReportErrorMacro(lastError, x)                                                  \
  do                                                                                               \
  {                                                                                                \
    std::ostringstream vtkRiemannMessage;                                                         \
    vtkRiemannMessage x;                                                                           \
    (lastError) = vtkRiemannMessage.str();                                                         \
    vtkErrorMacro(<< (lastError));                                                                 \
  } while (false)

#endif
