#include "Distributed.h"

#include "vtkAbstractArray.h"
#include "vtkAlgorithm.h"
#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommunicator.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"
#include "vtkXMLPImageDataWriter.h"
#include "vtkXMLPPolyDataWriter.h"
#include <vtksys/Directory.hxx>
#include <vtksys/SystemTools.hxx>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <map>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace riemann
{
namespace cli
{
namespace
{
vtkMultiProcessController* Controller()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  return controller && controller->GetNumberOfProcesses() > 1 ? controller : nullptr;
}

/// The lowest failing rank, once this rank knows that one failed (it told,
/// or was told): no collective follows then. -1 while none has.
int KnownFailedRank = -1;

/// The lowest rank whose `ok` is false, or NumberOfRanks() if none.
int LowestFailingRank(bool ok)
{
  vtkMultiProcessController* controller = Controller();
  if (!controller)
  {
    return ok ? 1 : 0;
  }
  const long long mine = ok ? NumberOfRanks() : Rank();
  long long lowest = mine;
  controller->AllReduce(&mine, &lowest, 1, vtkCommunicator::MIN_OP);
  return static_cast<int>(lowest);
}

/// Collective: every rank's `piece`, in rank order, on rank 0 (nothing on the others).
std::vector<vtkSmartPointer<vtkDataObject>> GatherOnRankZero(vtkDataObject* piece)
{
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  Controller()->Gather(piece, pieces, 0);
  return pieces;
}

/// Whether a file name is one of the piece files VTK's parallel writers make
/// for `base` ("base_3.vtp").
bool IsPieceFileOf(const std::string& name, const std::string& base)
{
  const std::string prefix = base + "_";
  if (name.compare(0, prefix.size(), prefix) != 0)
  {
    return false;
  }
  const size_t dot = name.rfind('.');
  if (dot == std::string::npos || dot <= prefix.size())
  {
    return false;
  }
  return name.find_first_not_of("0123456789", prefix.size()) == dot;
}

/// Replace folder `target` (if it exists, it must hold only piece files of
/// `base`: another folder of that name is the user's) by `source`.
/// An exclusive flock() on a folder while this lives (released by close;
/// nothing is created). Without a lock (a file system that has none) the
/// step goes on unlocked, as before.
class FolderLock
{
public:
  explicit FolderLock(const std::string& folder)
    : Descriptor(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC))
  {
    if (this->Descriptor >= 0)
    {
      while (::flock(this->Descriptor, LOCK_EX) != 0 && errno == EINTR)
      {
      }
    }
  }
  ~FolderLock()
  {
    if (this->Descriptor >= 0)
    {
      ::close(this->Descriptor); // releases the lock
    }
  }
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

private:
  int Descriptor;
};

bool ReplacePieceFolder(const std::string& source, const std::string& target,
  const std::string& base, std::string& problem)
{
  if (vtksys::SystemTools::FileExists(target))
  {
    vtksys::Directory listing;
    if (!vtksys::SystemTools::FileIsDirectory(target) || !listing.Load(target))
    {
      problem = target + " exists and is not a folder of piece files";
      return false;
    }
    for (unsigned long i = 0; i < listing.GetNumberOfFiles(); ++i)
    {
      const std::string name = listing.GetFile(i);
      if (name != "." && name != ".." && !IsPieceFileOf(name, base))
      {
        problem = target + "/ holds files other than pieces of " + base + " (" + name +
          "): move it away first";
        return false;
      }
    }
    if (!vtksys::SystemTools::RemoveADirectory(target))
    {
      problem = "cannot remove the old pieces in " + target;
      return false;
    }
  }
  if (std::rename(source.c_str(), target.c_str()) != 0)
  {
    problem = "cannot move the pieces into " + target;
    return false;
  }
  return true;
}

/// `target`'s arrays put in `model`'s order, with `model`'s active attributes
/// (VTK's marshalling of data objects moves the attribute arrays first).
void MatchArrayOrder(vtkDataSetAttributes* target, vtkDataSetAttributes* model)
{
  std::vector<vtkSmartPointer<vtkAbstractArray>> ordered;
  for (int a = 0; a < model->GetNumberOfArrays(); ++a)
  {
    const char* name = model->GetAbstractArray(a)->GetName();
    if (vtkAbstractArray* array = name ? target->GetAbstractArray(name) : nullptr)
    {
      ordered.emplace_back(array);
    }
  }
  for (int a = 0; a < target->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = target->GetAbstractArray(a);
    if (std::find(ordered.begin(), ordered.end(), array) == ordered.end())
    {
      ordered.emplace_back(array);
    }
  }
  while (target->GetNumberOfArrays() > 0)
  {
    target->RemoveArray(0);
  }
  for (const vtkSmartPointer<vtkAbstractArray>& array : ordered)
  {
    target->AddArray(array);
  }
  for (int attribute = 0; attribute < vtkDataSetAttributes::NUM_ATTRIBUTES; ++attribute)
  {
    vtkAbstractArray* active = model->GetAbstractAttribute(attribute);
    if (active && active->GetName())
    {
      target->SetActiveAttribute(active->GetName(), attribute);
    }
  }
}

/// `data` with each ghost point replaced by its owner's copy (the point with
/// the same `keys` values that is not a ghost), and the ghost array dropped.
vtkSmartPointer<vtkPolyData> ReplaceGhostsByOwners(
  vtkPolyData* data, const std::vector<std::string>& keys)
{
  vtkPointData* inPD = data->GetPointData();
  auto* ghosts =
    vtkUnsignedCharArray::SafeDownCast(inPD->GetArray(vtkDataSetAttributes::GhostArrayName()));
  std::vector<vtkDataArray*> keyArrays;
  for (const std::string& name : keys)
  {
    keyArrays.push_back(inPD->GetArray(name.c_str()));
  }
  if (!ghosts || keyArrays.empty() ||
    std::find(keyArrays.begin(), keyArrays.end(), nullptr) != keyArrays.end())
  {
    return data;
  }
  auto keyOf = [&](vtkIdType id)
  {
    std::vector<double> key;
    for (vtkDataArray* array : keyArrays)
    {
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
      {
        key.push_back(array->GetComponent(id, c));
      }
    }
    return key;
  };
  // Owned points first, in order: the ids they have in the one-process output's order.
  const vtkIdType n = data->GetNumberOfPoints();
  auto result = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(data->GetPoints()->GetDataType());
  vtkPointData* outPD = result->GetPointData();
  outPD->CopyFieldOff(vtkDataSetAttributes::GhostArrayName());
  outPD->CopyAllocate(inPD, n);
  std::vector<vtkIdType> newIds(static_cast<size_t>(n), -1);
  std::map<std::vector<double>, vtkIdType> owners;
  for (vtkIdType id = 0; id < n; ++id)
  {
    if (ghosts->GetValue(id) == 0)
    {
      newIds[id] = points->InsertNextPoint(data->GetPoint(id));
      outPD->CopyData(inPD, id, newIds[id]);
      owners[keyOf(id)] = newIds[id];
    }
  }
  for (vtkIdType id = 0; id < n; ++id)
  {
    if (newIds[id] < 0)
    {
      const auto owner = owners.find(keyOf(id));
      if (owner != owners.end())
      {
        newIds[id] = owner->second;
      }
      else // no piece owns it: keep the copy
      {
        newIds[id] = points->InsertNextPoint(data->GetPoint(id));
        outPD->CopyData(inPD, id, newIds[id]);
      }
    }
  }
  result->SetPoints(points);
  auto remap = [&](vtkCellArray* cells)
  {
    vtkNew<vtkCellArray> remapped;
    vtkNew<vtkIdList> cell;
    for (cells->InitTraversal(); cells->GetNextCell(cell);)
    {
      for (vtkIdType k = 0; k < cell->GetNumberOfIds(); ++k)
      {
        cell->SetId(k, newIds[cell->GetId(k)]);
      }
      remapped->InsertNextCell(cell);
    }
    return remapped;
  };
  result->SetVerts(remap(data->GetVerts()));
  result->SetLines(remap(data->GetLines()));
  result->SetPolys(remap(data->GetPolys()));
  result->SetStrips(remap(data->GetStrips()));
  result->GetCellData()->ShallowCopy(data->GetCellData());
  result->GetFieldData()->ShallowCopy(data->GetFieldData());
  return result;
}
} // namespace

int Rank()
{
  vtkMultiProcessController* controller = Controller();
  return controller ? controller->GetLocalProcessId() : 0;
}

int NumberOfRanks()
{
  vtkMultiProcessController* controller = Controller();
  return controller ? controller->GetNumberOfProcesses() : 1;
}

bool IsDistributed()
{
  return Controller() != nullptr;
}

bool LaunchedByMpiLauncher()
{
  for (const char* variable : { "OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK" })
  {
    const char* value = std::getenv(variable);
    if (value && *value)
    {
      return true;
    }
  }
  return false;
}

StoppedByAnotherRank::StoppedByAnotherRank(int failedRank)
  : Failure("stopped: rank " + std::to_string(failedRank) + " failed", 1)
  , FailedRank(failedRank)
{
}

void AgreeToGoOn()
{
  AgreeOnOutcome(true, std::string());
}

void AgreeOnOutcome(bool ok, const std::string& failure, const std::function<void()>& cleanUp)
{
  if (!Controller() || KnownFailedRank >= 0)
  {
    if (!ok)
    {
      throw Failure(failure);
    }
    return;
  }
  const int failed = LowestFailingRank(ok);
  if (failed < NumberOfRanks())
  {
    KnownFailedRank = failed;
    if (cleanUp)
    {
      cleanUp();
    }
    if (!ok)
    {
      throw Failure(failure);
    }
    throw StoppedByAnotherRank(failed);
  }
}

bool TellOthersOfFailure()
{
  if (!Controller())
  {
    return true;
  }
  if (KnownFailedRank < 0)
  {
    KnownFailedRank = LowestFailingRank(false);
  }
  return KnownFailedRank == Rank();
}

std::vector<long long> SumOverRanks(std::vector<long long> values)
{
  vtkMultiProcessController* controller = Controller();
  if (!controller)
  {
    return values;
  }
  std::vector<long long> sums(values.size());
  controller->AllReduce(
    values.data(), sums.data(), static_cast<vtkIdType>(values.size()), vtkCommunicator::SUM_OP);
  return sums;
}

double SumOverRanks(double value)
{
  vtkMultiProcessController* controller = Controller();
  double sum = value;
  if (controller)
  {
    controller->AllReduce(&value, &sum, 1, vtkCommunicator::SUM_OP);
  }
  return sum;
}

void UpdateThisRanksPiece(vtkAlgorithm* algorithm)
{
  // The same request on every output port, so that a writer of another
  // port (expmap's wavefronts) asks for what was made, not a new execution.
  using SDDP = vtkStreamingDemandDrivenPipeline;
  algorithm->UpdateInformation();
  for (int port = 1; port < algorithm->GetNumberOfOutputPorts(); ++port)
  {
    vtkInformation* info = algorithm->GetOutputInformation(port);
    info->Set(SDDP::UPDATE_PIECE_NUMBER(), Rank());
    info->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), NumberOfRanks());
    info->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  }
  algorithm->UpdatePiece(Rank(), NumberOfRanks(), 0);
  // Fault injection for the tests (TestCliMpi.py): the rank that
  // RIEMANN_TEST_FAILING_RANK names fails here, as a rank whose computation
  // fails would, while the others go on to their next agreement point.
  const char* failing = std::getenv("RIEMANN_TEST_FAILING_RANK");
  if (failing && *failing && IsDistributed() && std::atoi(failing) == Rank())
  {
    throw Failure(
      "rank " + std::to_string(Rank()) + " failed on purpose (RIEMANN_TEST_FAILING_RANK is set)");
  }
}

vtkSmartPointer<vtkPolyData> GatherPolyData(
  vtkPolyData* piece, const std::vector<std::string>& ghostKeys)
{
  if (!IsDistributed())
  {
    return piece;
  }
  const std::vector<vtkSmartPointer<vtkDataObject>> pieces = GatherOnRankZero(piece);
  if (Rank() != 0)
  {
    return nullptr;
  }
  // Empty pieces carry no arrays; vtkAppendPolyData keeps only the arrays
  // every input has, so they are left out.
  vtkNew<vtkAppendPolyData> append;
  for (const vtkSmartPointer<vtkDataObject>& received : pieces)
  {
    auto* part = vtkPolyData::SafeDownCast(received);
    if (part && part->GetNumberOfPoints() > 0)
    {
      append->AddInputData(part);
    }
  }
  if (append->GetNumberOfInputConnections(0) == 0)
  {
    return vtkSmartPointer<vtkPolyData>::New();
  }
  append->Update();
  vtkSmartPointer<vtkPolyData> all = ReplaceGhostsByOwners(append->GetOutput(), ghostKeys);
  if (piece->GetNumberOfPoints() > 0)
  {
    MatchArrayOrder(all->GetPointData(), piece->GetPointData());
    MatchArrayOrder(all->GetCellData(), piece->GetCellData());
  }
  return all;
}

vtkSmartPointer<vtkImageData> GatherImage(vtkImageData* piece, const int wholeExtent[6])
{
  if (!IsDistributed())
  {
    return piece;
  }
  const std::vector<vtkSmartPointer<vtkDataObject>> pieces = GatherOnRankZero(piece);
  if (Rank() != 0)
  {
    return nullptr;
  }
  // The arrays in the order and with the attributes of this rank's own
  // piece (VTK's marshalling of data objects reorders them), or of the first
  // piece that has points.
  vtkImageData* model = piece;
  for (size_t r = 0; model->GetNumberOfPoints() == 0 && r < pieces.size(); ++r)
  {
    auto* part = vtkImageData::SafeDownCast(pieces[r]);
    model = part && part->GetNumberOfPoints() > 0 ? part : model;
  }
  auto whole = vtkSmartPointer<vtkImageData>::New();
  // The geometry from this rank's own piece: the marshalling writes origin
  // and spacing as 6-digit text (the arrays go as exact binary).
  whole->SetExtent(const_cast<int*>(wholeExtent));
  whole->SetSpacing(piece->GetSpacing());
  whole->SetOrigin(piece->GetOrigin());
  whole->SetDirectionMatrix(piece->GetDirectionMatrix());
  whole->GetFieldData()->ShallowCopy(model->GetFieldData());
  vtkPointData* modelPD = model->GetPointData();
  vtkPointData* wholePD = whole->GetPointData();
  for (int a = 0; a < modelPD->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* source = modelPD->GetAbstractArray(a);
    vtkSmartPointer<vtkAbstractArray> array = vtk::TakeSmartPointer(source->NewInstance());
    array->SetName(source->GetName());
    array->SetNumberOfComponents(source->GetNumberOfComponents());
    array->SetNumberOfTuples(whole->GetNumberOfPoints());
    wholePD->AddArray(array);
  }
  for (int attribute = 0; attribute < vtkDataSetAttributes::NUM_ATTRIBUTES; ++attribute)
  {
    vtkAbstractArray* active = modelPD->GetAbstractAttribute(attribute);
    if (active && active->GetName())
    {
      wholePD->SetActiveAttribute(active->GetName(), attribute);
    }
  }
  // Each piece's rows of points into their place in the whole extent.
  for (const vtkSmartPointer<vtkDataObject>& received : pieces)
  {
    auto* part = vtkImageData::SafeDownCast(received);
    if (!part || part->GetNumberOfPoints() == 0)
    {
      continue;
    }
    const int* extent = part->GetExtent();
    const vtkIdType row = extent[1] - extent[0] + 1;
    for (int a = 0; a < wholePD->GetNumberOfArrays(); ++a)
    {
      vtkAbstractArray* target = wholePD->GetAbstractArray(a);
      vtkAbstractArray* source = part->GetPointData()->GetAbstractArray(target->GetName());
      if (!source)
      {
        continue;
      }
      vtkIdType from = 0;
      for (int k = extent[4]; k <= extent[5]; ++k)
      {
        for (int j = extent[2]; j <= extent[3]; ++j, from += row)
        {
          int start[3] = { extent[0], j, k };
          target->InsertTuples(whole->ComputePointId(start), row, from, source);
        }
      }
    }
  }
  return whole;
}

std::vector<char> GatherBytes(const std::vector<char>& bytes)
{
  vtkMultiProcessController* controller = Controller();
  if (!controller)
  {
    return bytes;
  }
  const int ranks = NumberOfRanks();
  const long long length = static_cast<long long>(bytes.size());
  std::vector<long long> lengths(static_cast<size_t>(ranks), 0);
  controller->Gather(&length, lengths.data(), 1, 0);
  std::vector<vtkIdType> counts(lengths.begin(), lengths.end());
  std::vector<vtkIdType> offsets(counts.size(), 0);
  for (size_t r = 1; r < counts.size(); ++r)
  {
    offsets[r] = offsets[r - 1] + counts[r - 1];
  }
  std::vector<char> all;
  if (Rank() == 0)
  {
    all.resize(static_cast<size_t>(offsets.back() + counts.back()));
  }
  controller->GatherV(bytes.data(), all.data(), static_cast<vtkIdType>(bytes.size()), counts.data(),
    offsets.data(), 0);
  return all;
}

OutputLayout ChooseOutputLayout(const std::string& option, const std::string& path, bool gather,
  const std::string& piecesExtension)
{
  const std::string extension = Extension(path);
  if (extension == "pvtp" || extension == "pvti")
  {
    if (gather)
    {
      throw Failure(option + " " + path + ": --gather writes one file (." + extension.substr(1) +
          "); ." + extension + " is the format of pieces",
        2);
    }
    return OutputLayout::Pieces;
  }
  if (!IsDistributed())
  {
    return OutputLayout::SingleFile;
  }
  if (!gather)
  {
    throw Failure(option + " " + path + ": " + std::to_string(NumberOfRanks()) +
        " ranks write their pieces in VTK's parallel format (." + piecesExtension +
        "), or add --gather for one file written by rank 0",
      2);
  }
  return OutputLayout::Gathered;
}

void AddGatherOption(CLI::App* command, bool& gather)
{
  command->add_flag("--gather", gather,
    "Under mpirun: gather the ranks' pieces on rank 0 and write one file (without it, "
    "outputs are .pvtp/.pvti pieces, one file per rank)");
}

void WritePieces(
  vtkAlgorithm* producer, int port, const std::string& path, const std::string& compress)
{
  // The piece folder is named after the summary, as VTK's writers name it
  // ("out.pvtp" -> "out/out_0.vtp"); a staging folder next to it holds both
  // until every rank has written.
  const std::string folder = vtksys::SystemTools::GetFilenamePath(path);
  const std::string directory = folder.empty() ? std::string(".") : folder;
  const std::string name = vtksys::SystemTools::GetFilenameName(path);
  const std::string base = vtksys::SystemTools::GetFilenameWithoutLastExtension(path);
  // The staging folder is this job's own (rank 0's process id, which every
  // rank learns): two jobs writing one name once mixed their pieces in a
  // shared ".name.partial", and InterruptHandling removes it by that tag.
  const long long jobTag =
    SumOverRanks(std::vector<long long>{ Rank() == 0 ? static_cast<long long>(::getpid()) : 0 })
      .front();
  const std::string staging =
    directory + "/." + name + ".partial-" + std::to_string(jobTag);
  if (Rank() == 0)
  {
    vtksys::SystemTools::RemoveADirectory(staging);
    if (!vtksys::SystemTools::MakeDirectory(staging))
    {
      throw Failure("could not write " + path + ": cannot make " + staging +
        " (check that the folder exists and is writable)");
    }
  }
  AgreeToGoOn();

  vtkSmartPointer<vtkXMLPDataObjectWriter> writer;
  if (Extension(path) == "pvti")
  {
    writer = vtkSmartPointer<vtkXMLPImageDataWriter>::New();
  }
  else
  {
    writer = vtkSmartPointer<vtkXMLPPolyDataWriter>::New();
  }
  const std::string staged = staging + "/" + name;
  writer->SetFileName(staged.c_str());
  writer->SetInputConnection(producer->GetOutputPort(port));
  writer->SetController(vtkMultiProcessController::GetGlobalController());
  writer->SetNumberOfPieces(NumberOfRanks());
  writer->SetStartPiece(Rank());
  writer->SetEndPiece(Rank());
  writer->SetUseSubdirectory(true);
  writer->SetDataModeToAppended();
  SetCompressor(writer, compress);
  // Every rank takes part in the writer's own collectives; success is told after.
  const bool written = writer->Write() == 1 && writer->GetErrorCode() == 0;
  AgreeOnOutcome(written,
    "could not write rank " + std::to_string(Rank()) + "'s piece of " + path +
      " (check that its folder exists and is writable on every node)",
    [&]()
    {
      if (Rank() == 0)
      {
        vtksys::SystemTools::RemoveADirectory(staging);
      }
    });

  if (Rank() == 0)
  {
    // The pieces' folder and the summary are two renames: another job
    // writing the same name must not come between them (its summary would
    // list these pieces, or this one its pieces). An exclusive lock on the
    // output's folder makes the pair one step for every riemann job.
    const FolderLock lock(directory);
    std::string problem;
    const bool moved =
      ReplacePieceFolder(staging + "/" + base, directory + "/" + base, base, problem) &&
      std::rename(staged.c_str(), path.c_str()) == 0;
    vtksys::SystemTools::RemoveADirectory(staging);
    if (!moved)
    {
      throw Failure("could not write " + path + ": " +
        (problem.empty() ? "cannot move the summary file into place" : problem));
    }
  }
}

void WriteOutput(vtkAlgorithm* producer, int port, const std::string& path, OutputLayout layout,
  const std::string& compress, const std::vector<std::string>& ghostKeys,
  const std::function<bool(vtkPolyData*, const std::string&)>& writeFile)
{
  if (layout == OutputLayout::Pieces)
  {
    WritePieces(producer, port, path, compress);
    return;
  }
  vtkPolyData* piece = vtkPolyData::SafeDownCast(producer->GetOutputDataObject(port));
  const vtkSmartPointer<vtkPolyData> all = layout == OutputLayout::Gathered
    ? GatherPolyData(piece, ghostKeys)
    : vtkSmartPointer<vtkPolyData>(piece);
  if (Rank() == 0)
  {
    WriteAtomically(path,
      [&](const std::string& temporary) {
        return writeFile ? writeFile(all, temporary) : WritePolyDataFile(all, temporary, compress);
      });
  }
}
} // namespace cli
} // namespace riemann
