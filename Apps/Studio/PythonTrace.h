/**
 * @file PythonTrace.h
 * @brief The session as a Python script that rebuilds the same pipeline with
 * the toolkit's package (`import riemann`), as ParaView's trace does: the
 * metric (text, parameter values, time), the scene, the observer camera,
 * the inside view's ray settings, and one filter per item with the same
 * Set calls. Run as is, it updates every filter and writes each output to
 * a .vtp/.vti file (--output-dir).
 */
#ifndef RiemannStudio_PythonTrace_h
#define RiemannStudio_PythonTrace_h

#include <string>

namespace riemann
{
namespace studio
{
class StudioDocument;

std::string PythonScript(const StudioDocument& document);
}
}

#endif
