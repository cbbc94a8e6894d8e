// Shared by the C++ tests of every module: an ErrorEvent collector (VTK's
// CommonCore only, so that the filters' tests need no rendering).
#ifndef RiemannErrorObserver_h
#define RiemannErrorObserver_h

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkObject.h"

#include <string>
#include <vector>

namespace riemann
{
namespace testing
{
/// Collects the ErrorEvents of an object.
struct ErrorObserver
{
  vtkNew<vtkCallbackCommand> Command;
  std::vector<std::string> Messages;

  explicit ErrorObserver(vtkObject* object)
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback(
      [](vtkObject*, unsigned long, void* clientData, void* callData)
      {
        auto* self = static_cast<ErrorObserver*>(clientData);
        self->Messages.emplace_back(callData ? static_cast<const char*>(callData) : "");
      });
    object->AddObserver(vtkCommand::ErrorEvent, this->Command);
  }
  std::string All() const
  {
    std::string all;
    for (const std::string& m : this->Messages)
    {
      all += m + "\n";
    }
    return all;
  }
};
} // namespace testing
} // namespace riemann

#endif
