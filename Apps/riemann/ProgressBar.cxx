#include "ProgressBar.h"

#include "Distributed.h"

#include "vtkObject.h"

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace riemann
{
namespace cli
{
void ProgressBar::Observe(vtkObject* object, const std::string& label, bool show)
{
  // In an MPI job rank 0 draws its own piece's progress: the pieces are
  // equal shares of the work, so it stands for the job's.
  this->Label =
    IsDistributed() ? label + " (rank 0 of " + std::to_string(NumberOfRanks()) + ")" : label;
  this->Enabled = show && Rank() == 0;
  object->AddObserver(vtkCommand::ProgressEvent, this);
}

bool ProgressBar::StderrIsTerminal()
{
  return isatty(fileno(stderr)) != 0;
}

void ProgressBar::Execute(vtkObject*, unsigned long event, void* data)
{
  if (event != vtkCommand::ProgressEvent || !this->Enabled || !data)
  {
    return;
  }
  const double progress = *static_cast<double*>(data);
  const int percent = static_cast<int>(100.0 * std::min(1.0, std::max(0.0, progress)));
  if (percent == this->Shown)
  {
    return; // redraw only when the number changes
  }
  this->Shown = percent;
  constexpr int width = 30;
  const int filled = percent * width / 100;
  std::fprintf(stderr, "\r%s [%.*s%*s] %3d%%", this->Label.c_str(), filled,
    "##############################", width - filled, "", percent);
  std::fflush(stderr);
}

void ProgressBar::Finish()
{
  if (this->Enabled && this->Shown >= 0)
  {
    std::fprintf(stderr, "\n");
    this->Shown = -1;
  }
}
} // namespace cli
} // namespace riemann
