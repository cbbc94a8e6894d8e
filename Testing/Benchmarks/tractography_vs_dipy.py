#!/usr/bin/python3
"""Streamlines per second: `riemann trace` against DIPY's LocalTracking, in one run.

Both trace from the same seeds through the same tensors, both ways, at the
same step (0.5 mm), and stop where the FA falls below 0.2 (riemann:
`--stop-fa 0.2`, the FA of the tensor its metric's spline stands for;
DIPY: ThresholdStoppingCriterion on the fitted FA, trilinear); one tract a
seed. The tensors and masks are written as nibabel and DIPY write them
(the s-form only). Timed: the whole `riemann trace` process (start-up,
reading the NIfTI files, the spline, tracing on every core, writing the
.tck) against DIPY's deterministic LocalTracking loop (EuDX's direction
getter on the tensor's peak; one thread), whose peaks are computed
beforehand and not timed. With the Python bindings on PYTHONPATH, also
vtkRiemannGeodesicTracer in process (Update() alone: no start-up, no
files), with the same stop, from the seeds and directions the CLI traced
(one untimed run to a .vtp). Medians of --runs runs of each, interleaved
(the machine may be shared). Printed per case: seeds, time and tracts per
second of each, the ratio riemann / DIPY, the seeds that made no tract,
mean tract length and points per second (the .tck read with nibabel).

Cases:
1. small_64D: DIPY's 10^3-voxel scan (Examples/tractography_dipy.py fits and
   writes it), seeds at the centres of the voxels with FA > 0.3 (595):
   `--seed-mask`, DIPY's seeds_from_mask. So few and so short (riemann's
   16 mm, DIPY's 13) that riemann's start-up dominates.
2. small_64D x 27: the same mask, 27 seeds a voxel (seeds_from_mask density
   3, 16,065 seeds); riemann reads them, with DIPY's initial direction at
   each (its voxel's peak, in world axes), from a CSV (`--seeds`), since
   `--seeds-per-voxel` spreads its seeds at random. The 3,146 seeds beyond
   the outermost voxel centres made no tract in riemann when these figures
   were measured (its volume then ended at those centres; it now reaches
   the outer voxels' faces, as DIPY's and MRtrix's do); DIPY's 4,646
   untraced seeds are all but 118 in the outer layer of voxels; 211 more
   made none in riemann, where the spline's FA is below 0.2 at the seed.
3. synthetic: 64 x 64 x 32 voxels of 2 mm (128 x 128 x 64 mm), FA 0.80
   everywhere (the FA stop never acts), fibres along x waving in y
   (direction (1, 0.8 cos(2 pi x / 40 mm), 0)); seeds at the centres of
   every other voxel in each axis, inside (31 x 31 x 15 = 14,415); most
   tracts cross the volume, 145 mm (on average riemann's 130 mm, DIPY's
   110: tracts seeded near the y faces wave out through them). Its metric
   is D^-1 scaled by the largest eigenvalue, so that arc length is length
   in mm along the fibres. DIPY's peaks are the tensors' e1 on the sphere
   (peaks_from_model on 131,072 voxels would take minutes and measure
   nothing here).

Each case is timed for both of the sampled metric's "christoffel" choices
(--christoffel, default spline,voxels): the exact spline's symbols, and the
fast path's g and dg sampled at the voxels and interpolated trilinearly.
Measured with riemann 1d8b514 and DIPY 1.6 on 2 cores (load 0.9), --runs 3
(tracts per second; riemann / DIPY, in process in brackets):
    case            christoffel  seeds   riemann trace  in process  DIPY     riemann / DIPY
    small_64D       spline         595    9,724         17,803      73,689   0.13 (0.24)
                    voxels         595   17,199         79,927      73,689   0.23 (1.08)
    small_64D x 27  spline      16,065   16,892         19,262      83,165   0.20 (0.23)
                    voxels      16,065   51,913         86,986      83,165   0.62 (1.05)
    synthetic       spline      14,415    2,692          2,877      14,552   0.19 (0.20)
                    voxels      14,415    9,423         12,716      14,552   0.65 (0.87)
Untraced seeds, riemann / DIPY: 8 / 152, 3,357 / 4,646, 0 / 0; mean tract
length, riemann / DIPY: 16.3 / 12.6 mm, 18.8 / 13.0 mm, 130.4 / 109.5 mm.
Run: RIEMANN_EXECUTABLE=build/bin/riemann PYTHONPATH=build/lib/python3/dist-packages \
       /usr/bin/python3 Testing/Benchmarks/tractography_vs_dipy.py [--runs 5] [--cases 1,2,3]
Needs DIPY and nibabel (python3-dipy, python3-nibabel); not a test dependency.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "Examples"))
try:
    import numpy as np
    import nibabel as nib
    import dipy  # noqa: F401
except ImportError as missing:
    print(f"tractography_vs_dipy.py: skipped: needs DIPY and nibabel ({missing})")
    sys.exit(0)
import tractography_dipy as example  # noqa: E402
from dipy.data import default_sphere  # noqa: E402
from dipy.direction import peaks_from_model  # noqa: E402
from dipy.direction.peaks import PeaksAndMetrics  # noqa: E402
from dipy.io.utils import nifti1_symmat  # noqa: E402
from dipy.reconst.dti import TensorModel, lower_triangular  # noqa: E402
from dipy.tracking.local_tracking import LocalTracking  # noqa: E402
from dipy.tracking.stopping_criterion import ThresholdStoppingCriterion  # noqa: E402
from dipy.tracking.utils import seeds_from_mask  # noqa: E402

STEP = 0.5
# The sphere of DIPY's peaks: default_sphere subdivided twice (about 2.7
# degrees between directions), as in the example.
SPHERE = default_sphere.subdivide(2)


def time_riemann(command):
    """Wall time of one run of `command`."""
    start = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed:\n{done.stderr}")
    return seconds


def time_dipy(peaks, fa, affine, seeds):
    """(seconds of one LocalTracking loop, its streamlines)."""
    start = time.perf_counter()
    # One streamline a seed (max_cross=1, return_all=True), as the example.
    streamlines = list(LocalTracking(peaks, ThresholdStoppingCriterion(fa, 0.2), seeds, affine,
                                     step_size=STEP, max_cross=1, return_all=True))
    return time.perf_counter() - start, streamlines


def cli_seeds(tracts):
    """The seeds of a `riemann trace` .vtp and their directions: each line's
    first point and velocity, one line a seed (a seed that made no geodesic
    has none)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

    reader = vtkXMLPolyDataReader()
    reader.SetFileName(tracts)
    reader.Update()
    polydata = reader.GetOutput()
    first = vtk_to_numpy(polydata.GetLines().GetOffsetsArray())[:-1]
    first_points = vtk_to_numpy(polydata.GetLines().GetConnectivityArray())[first]
    seed_ids = vtk_to_numpy(polydata.GetCellData().GetArray("SeedIds"))
    _, one_line = np.unique(seed_ids, return_index=True)
    points = vtk_to_numpy(polydata.GetPoints().GetData())[first_points[one_line]]
    velocity = vtk_to_numpy(polydata.GetPointData().GetArray("Velocity"))[first_points[one_line]]
    return points.astype(float), velocity.astype(float)


def in_process_tracer(metric_path, points, directions, length):
    """vtkRiemannGeodesicTracer set up as `riemann trace` sets it up, from
    the same metric file, seeds and directions, or None without the Python
    bindings. Update() is then the tracing alone: no start-up, no files.
    (The seeds are given as points: the mask's placement is the CLI's
    reader's, and a mask placed here with VTK's direction matrix makes its
    own rounding at the volume's faces.)"""
    try:
        import riemann
    except ImportError:
        return None
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData

    metric = riemann.vtkRiemannMetric()
    if not metric.SetDefinitionFile(metric_path):
        sys.exit(metric.GetLastError())
    tracer = riemann.vtkRiemannGeodesicTracer()
    tracer.SetMetric(metric)
    tracer.SetIntegrationDirectionToBoth()
    settings = tracer.GetIntegrationSettings()
    settings.SetIntegratorTypeToRungeKutta4()
    settings.SetInitialIntegrationStep(STEP)
    settings.SetMaximumPropagation(length)
    tracer.SetStopFractionalAnisotropy(example.STOP_FA)
    seeds = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(points.copy(), deep=1))
    seeds.SetPoints(vtk_points)
    direction = numpy_to_vtk(directions.copy(), deep=1)
    direction.SetName("Direction")
    seeds.GetPointData().AddArray(direction)
    tracer.SetInputData(seeds)
    return tracer


def time_in_process(tracer):
    tracer.Modified()
    start = time.perf_counter()
    tracer.Update()
    return time.perf_counter() - start, tracer.GetOutput().GetNumberOfPoints()


def riemann_tracts(path):
    """The points and the length in mm of each tract of a .tck (one a traced
    seed, both halves joined), read as DIPY users read it."""
    tracts, _ = example.read_tracts(path)
    return np.array([len(t) for t in tracts]), np.array([example.length(t) for t in tracts])


def write_seeds(path, seeds, directions):
    with open(path, "w") as f:
        f.write("x,y,z,dx,dy,dz\n")
        for p, d in zip(seeds, directions):
            f.write(",".join(repr(float(c)) for c in (*p, *d)) + "\n")


def small_64d(folder, density):
    """Case 1 (density 1) or 2: (seeds, metric, riemann's seed options, DIPY's peaks, FA, affine)."""
    data, affine, gtab, _ = example.load_scan()
    fit = TensorModel(gtab).fit(data)
    fa = example.fractional_anisotropy(fit)
    mask = fa > example.SEED_FA
    paths = example.write_inputs(folder, fit, fa, affine)
    peaks = peaks_from_model(TensorModel(gtab), data, SPHERE, relative_peak_threshold=0.5,
                             min_separation_angle=25, mask=data[..., 0] > 0, npeaks=1)
    seeds = seeds_from_mask(mask, affine, density=density)
    if density == 1:
        return seeds, paths["metric.json"], {"seed_mask": paths["mask.nii.gz"]}, peaks, fa, affine
    # DIPY's initial direction: its voxel's peak (voxel axes), turned to world axes.
    voxels = np.rint(example.to_voxels(affine, seeds)).astype(int)
    rotation = affine[:3, :3] / np.linalg.norm(affine[:3, :3], axis=0)
    directions = peaks.peak_dirs[tuple(voxels.T)][:, 0] @ rotation.T
    csv = os.path.join(folder, "seeds.csv")
    write_seeds(csv, seeds, directions)
    return seeds, paths["metric.json"], {"seeds": csv}, peaks, fa, affine


def synthetic(folder, shape=(64, 64, 32), spacing=2.0):
    """Case 3: waving fibres along x, FA 0.80 (see the docstring)."""
    affine = np.diag([spacing, spacing, spacing, 1.0])
    x = np.arange(shape[0]) * spacing
    e1 = np.zeros(shape + (3,))
    e1[..., 0] = 1.0
    e1[..., 1] = (0.8 * np.cos(2 * np.pi * x / 40.0))[:, None, None]
    e1 /= np.linalg.norm(e1, axis=-1, keepdims=True)
    along, across = 1.7e-3, 0.3e-3
    tensors = across * np.eye(3) + (along - across) * e1[..., :, None] * e1[..., None, :]
    nib.save(nifti1_symmat(lower_triangular(tensors).astype(np.float32), affine),
             os.path.join(folder, "tensors.nii.gz"))
    mask = np.zeros(shape, dtype=np.uint8)
    mask[1:-1:2, 1:-1:2, 1:-1:2] = 1
    nib.save(nib.Nifti1Image(mask, affine), os.path.join(folder, "mask.nii.gz"))
    metric = os.path.join(folder, "metric.json")
    with open(metric, "w") as f:
        # Voxel axes are world axes here (no rotation): "world" is DIPY's frame.
        # The scale makes g = 1 along e1: arc length is mm along the fibres.
        json.dump({"type": "sampled", "file": "tensors.nii.gz", "tensor_metric": "inverse", "scale": along,
                   "outside": "stop", "frame": "world"}, f)
    # DIPY's peaks by hand: each voxel's e1 on the sphere (one peak).
    peaks = PeaksAndMetrics()
    peaks.sphere = SPHERE
    flat = e1.reshape(-1, 3)
    index = np.concatenate([np.argmax(np.abs(chunk @ SPHERE.vertices.T), axis=1)
                            for chunk in np.array_split(flat, max(1, len(flat) // 8192))])
    peaks.peak_indices = index.reshape(shape + (1,)).astype(np.int32)
    peaks.peak_dirs = SPHERE.vertices[peaks.peak_indices]
    peaks.peak_values = np.ones(shape + (1,))
    peaks.qa = peaks.peak_values
    # FA of eigenvalues (along, across, across): (along - across) / |eigenvalues| = 0.80.
    fa = np.full(shape, (along - across) / np.sqrt(along ** 2 + 2 * across ** 2))
    seeds = seeds_from_mask(mask.astype(bool), affine, density=1)
    return seeds, metric, {"seed_mask": os.path.join(folder, "mask.nii.gz")}, peaks, fa, affine


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--riemann", default=example.riemann_executable())
    parser.add_argument("--runs", type=int, default=5, help="runs of each, median (default 5)")
    parser.add_argument("--cases", default="1,2,3")
    parser.add_argument("--christoffel", default="spline,voxels",
                        help="the sampled metric's \"christoffel\" choices to time (default both)")
    parser.add_argument("--length", type=float, default=300.0,
                        help="riemann's arc length each way (default 300: tracts end at the volume's faces)")
    args = parser.parse_args()
    cases = {"1": ("small_64D", lambda f: small_64d(f, 1)), "2": ("small_64D x 27", lambda f: small_64d(f, 3)),
             "3": ("synthetic 64x64x32", synthetic)}
    print(f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f} at the start")
    rows = []
    for key in args.cases.split(","):
        name, make = cases[key]
        with tempfile.TemporaryDirectory() as folder:
            seeds, metric, seed_options, peaks, fa, affine = make(folder)
            variants = {}
            for christoffel in args.christoffel.split(","):
                # The same metric with "christoffel": the spline's own symbols or the voxels'.
                with open(metric) as f:
                    definition = json.load(f)
                definition["christoffel"] = christoffel
                path = os.path.join(folder, f"metric-{christoffel}.json")
                with open(path, "w") as f:
                    json.dump(definition, f)
                output = os.path.join(folder, f"tracts-{christoffel}.tck")
                command = example.riemann_trace_command(args.riemann, path, output, step=STEP,
                                                        length=args.length, **seed_options)
                # The seeds and directions the CLI traces, for the tracer in process: once, untimed, as a .vtp.
                polylines = os.path.join(folder, "tracts.vtp")
                time_riemann(command[:command.index("-o") + 1] + [polylines] + command[command.index("-o") + 2:])
                variants[christoffel] = {"command": command, "output": output, "ours": [], "inside": [],
                                         "tracer": in_process_tracer(path, *cli_seeds(polylines), args.length)}
            # Interleaved, so that a change of load on a shared machine falls on all.
            theirs = []
            for run in range(args.runs):
                for variant in variants.values():
                    variant["ours"].append(time_riemann(variant["command"]))
                    if variant["tracer"] is not None:
                        seconds, variant["inside_points"] = time_in_process(variant["tracer"])
                        variant["inside"].append(seconds)
                seconds, streamlines = time_dipy(peaks, fa, affine, seeds)
                theirs.append(seconds)
            theirs = statistics.median(theirs)
            for variant in variants.values():
                variant["points"], variant["lengths"] = riemann_tracts(variant["output"])
        if len(streamlines) != len(seeds):
            sys.exit(f"{name}: DIPY returned {len(streamlines)} streamlines for {len(seeds)} seeds")
        their_points = np.array([len(s) for s in streamlines])
        their_lengths = np.array([example.length(s) for s in streamlines])
        n = len(seeds)
        print(f"{name}: {n} seeds")
        print(f"  DIPY LocalTracking: {theirs:.3f} s, {n / theirs:,.0f} tracts/s, "
              f"{their_points.sum() / theirs:,.0f} points/s; {int((their_points < 2).sum())} seeds made no tract; "
              f"mean length {their_lengths[their_points > 1].mean():.1f} mm, "
              f"{their_points[their_points > 1].mean():.0f} points")
        for christoffel, variant in variants.items():
            ours = statistics.median(variant["ours"])
            our_points, our_lengths = variant["points"], variant["lengths"]
            print(f"  riemann trace, \"christoffel\": \"{christoffel}\": $ {' '.join(variant['command'])}")
            print(f"    {ours:.3f} s, {n / ours:,.0f} tracts/s, {our_points.sum() / ours:,.0f} points/s; "
                  f"{n - len(our_points)} seeds made no tract; mean length "
                  f"{our_lengths.mean():.1f} mm, {our_points.mean():.0f} points")
            inside = statistics.median(variant["inside"]) if variant["inside"] else None
            if inside:
                print(f"    vtkRiemannGeodesicTracer in process: {inside:.3f} s, {n / inside:,.0f} tracts/s, "
                      f"{variant['inside_points'] / inside:,.0f} points/s")
            print(f"    riemann / DIPY, tracts/s: {theirs / ours:.2f}" +
                  (f" (in process: {theirs / inside:.2f})" if inside else ""))
            rows.append((name, christoffel, n, n / ours, n / inside if inside else float("nan"), n / theirs,
                         theirs / ours, theirs / inside if inside else float("nan")))
    print("\n| case | christoffel | seeds | riemann trace, tracts/s | in process, tracts/s | DIPY, tracts/s "
          "| riemann / DIPY (in process) |\n|---|---|---|---|---|---|---|")
    for name, christoffel, n, a, b, c, r, ri in rows:
        print(f"| {name} | {christoffel} | {n:,} | {a:,.0f} | {b:,.0f} | {c:,.0f} | {r:.2f} ({ri:.2f}) |")


if __name__ == "__main__":
    main()
