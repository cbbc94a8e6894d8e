// The ranks of an MPI job as the commands see them. `mpirun -np N riemann
// fields ...` runs N processes; each computes its piece of the output (VTK's
// piece request: UpdatePiece(rank, N, 0)) and the results are written as
// VTK's parallel formats or gathered on rank 0. All messaging goes through
// VTK's global vtkMultiProcessController (a vtkMPIController, set by
// riemann-mpi and by riemann-render under a launcher; see CliMpi.h). In a
// plain run there is none: one rank, and every function here is a no-op.
//
// The rule that keeps a failing rank from hanging the job: every collective
// operation of a command is reached by every rank. A rank that fails (a bad
// option, a file it cannot write) throws Failure as in a plain run; main()
// then tells the other ranks (TellOthersOfFailure), which meet that message
// at their next AgreeToGoOn() and stop too. So a command calls AgreeToGoOn()
// right before each collective step (a gather, a parallel write), with
// nothing that can throw in between, and main() calls it once more when the
// command returns.
#ifndef RiemannDistributed_h
#define RiemannDistributed_h

#include "CliUtilities.h" // For Failure

#include "vtkSmartPointer.h"

#include <functional>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkImageData;
class vtkPolyData;

namespace CLI
{
class App;
}

namespace riemann
{
namespace cli
{
/// This process's rank (0 without MPI).
int Rank();
/// The number of ranks (1 without MPI).
int NumberOfRanks();
/// Whether more than one rank runs this command.
bool IsDistributed();

/**
 * Whether this process was started by an MPI launcher (mpirun, mpiexec,
 * srun): Open MPI's OMPI_COMM_WORLD_SIZE, PMI's PMI_SIZE or PMIx's PMIX_RANK
 * is set. Read from the environment only, so `riemann` decides without
 * loading MPI.
 */
bool LaunchedByMpiLauncher();

/// Thrown on the ranks that stop because another rank failed; that rank
/// says why, these say nothing.
class StoppedByAnotherRank : public Failure
{
public:
  explicit StoppedByAnotherRank(int failedRank);
  int FailedRank;
};

/**
 * Collective: every rank calls it at the same point of a command. Returns
 * when no rank has failed; otherwise throws StoppedByAnotherRank.
 */
void AgreeToGoOn();

/**
 * Collective, for a step whose part may fail on some ranks: each passes
 * whether its part succeeded (`ok`) and what to say if not. Returns when all
 * succeeded. Otherwise every rank runs `cleanUp`, then the failing ranks
 * throw Failure(`failure`) (the lowest one reports it) and the others
 * StoppedByAnotherRank. In a single process: throws Failure if not `ok`.
 */
void AgreeOnOutcome(bool ok, const std::string& failure, const std::function<void()>& cleanUp = {});

/**
 * Called by main() on a rank whose command failed, unless it already
 * learned of another rank's failure: the collective that the other ranks'
 * next AgreeToGoOn() meets. Returns whether this rank is the one that
 * reports (the lowest failing rank), so that a failure every rank shares
 * (a usage error) is printed once.
 */
bool TellOthersOfFailure();

/// Collective: the sums over ranks of `values` (each rank passes as many).
std::vector<long long> SumOverRanks(std::vector<long long> values);
double SumOverRanks(double value);

/**
 * Update `algorithm`'s outputs for this rank's piece: UpdatePiece(rank, N, 0)
 * (the same request on every output port), or a plain Update in a single
 * process. For the tests, a job with RIEMANN_TEST_FAILING_RANK=r set fails
 * on rank r here (Failure), as a rank whose computation fails would.
 */
void UpdateThisRanksPiece(vtkAlgorithm* algorithm);

/**
 * Collective: the ranks' pieces appended in rank order on rank 0 (nullptr
 * on the others). Pieces with points marked as ghosts (vtkGhostType) hold
 * copies of points that another piece owns: with `ghostKeys`, the point-data
 * arrays that name a point across pieces (e.g. DirectionId and Radius), each
 * ghost is replaced by its owner's copy, so the result holds every point
 * once, as the one-process output does.
 */
vtkSmartPointer<vtkPolyData> GatherPolyData(
  vtkPolyData* piece, const std::vector<std::string>& ghostKeys = {});

/// Collective: the ranks' extents of one image assembled on rank 0 into
/// `wholeExtent` (nullptr on the others).
vtkSmartPointer<vtkImageData> GatherImage(vtkImageData* piece, const int wholeExtent[6]);

/**
 * Collective: each rank's bytes concatenated in rank order on rank 0 (the
 * others get nothing).
 */
std::vector<char> GatherBytes(const std::vector<char>& bytes);

/// How a command writes one output file.
enum class OutputLayout
{
  /// One file, written by the one process.
  SingleFile,
  /// One file, written by rank 0 after gathering the pieces (--gather).
  Gathered,
  /// VTK's parallel format (.pvti, .pvtp): a summary file and a folder with
  /// one piece file per rank, written by every rank.
  Pieces
};

/**
 * The layout of output `path` (given with `option`): .pvti/.pvtp are pieces;
 * other files need one process or --gather under mpirun (a usage error
 * otherwise, which names both ways: `piecesExtension`, the command's
 * parallel format, "pvti" or "pvtp", and --gather).
 */
OutputLayout ChooseOutputLayout(const std::string& option, const std::string& path, bool gather,
  const std::string& piecesExtension);

/// What the --output help of every command says of .pvti/.pvtp.
constexpr const char* PiecesHelp =
  "(VTK's parallel format: under mpirun, one piece file per rank in a folder named after it)";

/// Register --gather on `command` into `gather`.
void AddGatherOption(CLI::App* command, bool& gather);

/**
 * Collective: write the pieces of `producer`'s output `port` (this rank's
 * piece, already updated) as the parallel XML file `path` (.pvtp or .pvti),
 * whole or not at all: every rank writes into a folder next to `path`, and
 * only when all succeeded does rank 0 move the summary and the piece folder
 * (named after `path` without its extension) into place.
 */
void WritePieces(
  vtkAlgorithm* producer, int port, const std::string& path, const std::string& compress);

/**
 * Collective: write output `port` of `producer` (polygonal data, this rank's
 * piece already updated) to `path` as `layout` says: the pieces
 * (WritePieces), or one file written by rank 0 (gathered first under MPI,
 * with `ghostKeys` as GatherPolyData takes them) through `writeFile` (.csv
 * writers), else as a .vtp, whole or not at all.
 */
void WriteOutput(vtkAlgorithm* producer, int port, const std::string& path, OutputLayout layout,
  const std::string& compress, const std::vector<std::string>& ghostKeys = {},
  const std::function<bool(vtkPolyData*, const std::string&)>& writeFile = {});
} // namespace cli
} // namespace riemann

#endif
