#!/usr/bin/python3
"""Geodesic tractography of a diffusion scan no one here made, against DIPY.

    tractography_dipy.py [--output Documentation/figures/tractography-dipy.png]
                         [--workdir DIR] [--step 0.5] [--length 40] [--repeats 3]
                         [--riemann build/bin/riemann] [--qform]

The scan is DIPY's `small_64D` (dipy.data.get_fnames: 10^3 voxels of 2 mm,
one b0 and 64 directions at b = 1000, an oblique affine). DIPY fits the
tensors (dipy.reconst.dti.TensorModel) and they are saved as DIPY's
`dipy_fit_dti` saves them (dipy.io.utils.nifti1_symmat: the six lower-
triangular components, intent NIFTI_INTENT_SYMMATRIX, placed by the s-form
only). The metric is their inverse, in FSL's voxel frame, as DIPY fits them
with FSL-style bvecs (Documentation/MetricFormat.md, "sampled"):

    {"type": "sampled", "file": "tensors.nii.gz", "inverse": true,
     "scale": "mean-diffusivity", "outside": "stop", "repair": "clamp",
     "frame": "fsl"}

Seeds: every voxel with FA > 0.3 (a NIfTI mask with the scan's affine), at
its centre. `riemann trace --seed-mask` follows the geodesics both ways
along each seed's e1; DIPY's deterministic LocalTracking follows the
tensor's peak (peaks_from_model, EuDX's direction getter) from the same
seeds (seeds_from_mask, density 1) and stops where the FA falls below 0.2.
`riemann trace` has no FA stop yet: its tracts run to --length or out of
the volume, so the distances are printed twice, once for the whole tracts
and once with each half cut where the (trilinear) FA first falls below 0.2,
DIPY's rule. --length and --step are riemann's arc length, which is mm
only where the tissue is isotropic at the scan's median diffusivity: a mm
along a fibre is less arc length, a mm across one (or through a nearly
degenerate tensor) more.

Printed: seeds, the angle between riemann's first step and the seed
voxel's e1 (a check of the frame), the seeds that made no tract in each,
tracts per second of each on this machine (the whole `riemann trace`
process, start-up and output included; DIPY's LocalTracking loop, its
peaks not included, over the same seeds), and the mean closest-point
distance between the two tracts of each seed (symmetrised: the mean over
each tract's points of the distance to the other tract, averaged both
ways). The picture: over the FA of the middle slice, the tracts of its seeds, riemann's (orange, faded where
the FA is below 0.2) and DIPY's (cyan), and a few seeds' pairs one colour a
seed, in the slice's voxel plane (mm).

Run: RIEMANN_EXECUTABLE=build/bin/riemann /usr/bin/python3 Examples/tractography_dipy.py
Needs DIPY and nibabel (Debian: python3-dipy, python3-nibabel); without
them it says so and exits 0. Matplotlib draws the picture.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

try:
    # DIPY needs NumPy: without it, it is as absent.
    import numpy as np
    import nibabel as nib
    from dipy.core.gradients import gradient_table
    from dipy.data import default_sphere, get_fnames
    from dipy.direction import peaks_from_model
    from dipy.io.gradients import read_bvals_bvecs
    from dipy.io.utils import nifti1_symmat
    from dipy.reconst.dti import TensorModel, lower_triangular
    from dipy.tracking.local_tracking import LocalTracking
    from dipy.tracking.stopping_criterion import ThresholdStoppingCriterion
    from dipy.tracking.utils import seeds_from_mask
except ImportError as missing:
    print(f"tractography_dipy.py: skipped: needs DIPY and nibabel ({missing}); "
          "Debian: apt-get install python3-dipy python3-nibabel")
    sys.exit(0)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SEED_FA = 0.3
STOP_FA = 0.2


def riemann_executable():
    return os.environ.get("RIEMANN_EXECUTABLE", os.path.join(ROOT, "build", "bin", "riemann"))


def riemann_trace_command(riemann, metric, output, *, step, length, seed_mask=None, seeds=None,
                          seeds_per_voxel=1, propagation="both"):
    """The `riemann trace` command line: seeds from a mask (each voxel's
    centre, along e1) or a CSV of points and directions, traced both ways.
    The one place that knows the CLI's options, so that --stop-fa, --max-angle,
    --min-length and .tck/.trk output, when they come, are added here."""
    command = [riemann, "trace", "-m", metric, "--propagation", propagation,
               "--step", repr(float(step)), "--length", repr(float(length)), "-o", output]
    if seed_mask is not None:
        command += ["--seed-mask", seed_mask]
        if seeds_per_voxel != 1:
            command += ["--seeds-per-voxel", str(seeds_per_voxel)]
    else:
        command += ["--seeds", seeds]
    return command


def run_riemann(command, repeats):
    """Run `command` `repeats` times: (median wall time, the summary it printed)."""
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        done = subprocess.run(command, capture_output=True, text=True)
        times.append(time.perf_counter() - start)
        if done.returncode != 0:
            sys.exit(f"tractography_dipy.py: {' '.join(command)} failed:\n{done.stderr}")
    summary = (done.stdout + done.stderr).strip()
    return statistics.median(times), summary


def load_scan():
    """small_64D: (data, affine, gradient table, header)."""
    dwi, bval, bvec = get_fnames("small_64D")
    image = nib.load(dwi)
    bvals, bvecs = read_bvals_bvecs(bval, bvec)
    return np.asarray(image.get_fdata()), image.affine, gradient_table(bvals, bvecs), image.header


def fractional_anisotropy(fit):
    # Voxels whose fit degenerates give NaN: they are neither seeds nor tracked through.
    return np.clip(np.nan_to_num(fit.fa), 0.0, 1.0)


def write_inputs(folder, fit, fa, affine, qform=None):
    """tensors.nii.gz (as DIPY saves them), mask.nii.gz (FA > SEED_FA) and
    metric.json in `folder`; their paths. With `qform` (a header), the
    files are also given its q-form: nibabel and DIPY write the s-form only."""
    tensors = nifti1_symmat(lower_triangular(fit.quadratic_form).astype(np.float32), affine)
    mask = nib.Nifti1Image((fa > SEED_FA).astype(np.uint8), affine)
    if qform is not None:
        for image in (tensors, mask):
            image.set_qform(qform.get_qform(), code=int(qform["qform_code"]))
    paths = {name: os.path.join(folder, name) for name in ("tensors.nii.gz", "mask.nii.gz", "metric.json")}
    nib.save(tensors, paths["tensors.nii.gz"])
    nib.save(mask, paths["mask.nii.gz"])
    metric = {"type": "sampled", "file": "tensors.nii.gz", "inverse": True,
              # Steps and lengths in mm where the tissue is isotropic, whatever
              # the tensors' units (DIPY's are mm^2/s).
              "scale": "mean-diffusivity",
              "outside": "stop",
              # Fitted tensors of noisy voxels can have eigenvalues <= 0.
              "repair": "clamp",
              # DIPY's tensors are in the frame of FSL-style bvecs.
              "frame": "fsl"}
    with open(paths["metric.json"], "w") as f:
        json.dump(metric, f, indent=1)
    return paths


def read_polylines(path):
    """The lines of a .vtp: (list of point arrays, cell data as a dict of arrays)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    polydata = reader.GetOutput()
    points = vtk_to_numpy(polydata.GetPoints().GetData()).astype(float)
    offsets = vtk_to_numpy(polydata.GetLines().GetOffsetsArray())
    connectivity = vtk_to_numpy(polydata.GetLines().GetConnectivityArray())
    lines = [points[connectivity[offsets[c]:offsets[c + 1]]] for c in range(len(offsets) - 1)]
    cells = polydata.GetCellData()
    data = {cells.GetArrayName(i): vtk_to_numpy(cells.GetArray(i)) for i in range(cells.GetNumberOfArrays())}
    return lines, data


def to_voxels(affine, points):
    inverse = np.linalg.inv(affine)
    return points @ inverse[:3, :3].T + inverse[:3, 3]


def riemann_halves(path, affine, seed_voxels):
    """riemann's half tracts (each starting at its seed) by DIPY's seed index.
    They are matched by position, not by SeedIds: `--seed-mask` numbers the
    seeds in the order VTK's NIfTI reader stores the voxels (slices reversed
    for qfac -1), not numpy's."""
    lines, _ = read_polylines(path)
    index = {tuple(v): i for i, v in enumerate(seed_voxels)}
    halves = [[] for _ in seed_voxels]
    for line in lines:
        voxel = tuple(np.rint(to_voxels(affine, line[:1])[0]).astype(int))
        halves[index[voxel]].append(line)
    return halves


def join(halves):
    """One polyline through the seed from its (at most two) halves."""
    if not halves:
        return None
    if len(halves) == 1:
        return halves[0]
    return np.concatenate([halves[1][::-1], halves[0][1:]])


def seed_angles(halves, fit, seed_voxels, affine):
    """Per traced seed, the angle (degrees) between riemann's first step and
    the seed voxel's e1 as DIPY fitted it, turned to world axes: a check of
    the frame ("fsl"). Not 0: riemann's g is a B-spline, which blends each
    sample with its neighbours' (MetricFormat.md), and this scan is noisy."""
    axes = affine[:3, :3] / np.linalg.norm(affine[:3, :3], axis=0)
    angles = []
    for h, voxel in zip(halves, seed_voxels):
        if h:
            step = (h[0][1] - h[0][0]) / np.linalg.norm(h[0][1] - h[0][0])
            e1 = axes @ fit.evecs[tuple(voxel)][:, 0]
            angles.append(np.degrees(np.arccos(min(1.0, abs(float(step @ e1))))))
    return np.array(angles)


def cut_at_low_fa(half, fa, affine):
    """`half` up to and including its first point where the trilinear FA is
    below STOP_FA (DIPY's ThresholdStoppingCriterion)."""
    from scipy.ndimage import map_coordinates

    values = map_coordinates(fa, to_voxels(affine, half).T, order=1, mode="nearest")
    low = np.nonzero(values[1:] < STOP_FA)[0]
    return half if len(low) == 0 else half[:low[0] + 2]


def dipy_tracts(data, fa, affine, gtab, seeds, step):
    """DIPY's deterministic tracking from `seeds`: (streamlines in seed
    order, seconds of the tracking loop, seconds of the peaks)."""
    start = time.perf_counter()
    # A tensor has one principal direction: one peak; the sphere subdivided
    # twice (5762 directions, about 2.7 degrees apart) so that EuDX's
    # direction getter, which steps along sphere vertices, is not held to
    # default_sphere's 10 degrees.
    peaks = peaks_from_model(TensorModel(gtab), data, default_sphere.subdivide(2),
                             relative_peak_threshold=0.5, min_separation_angle=25,
                             mask=data[..., 0] > 0, npeaks=1)
    peak_seconds = time.perf_counter() - start
    start = time.perf_counter()
    # max_cross=1 and return_all=True: exactly one streamline per seed, in
    # seed order (a seed without a direction gives its one point).
    streamlines = list(LocalTracking(peaks, ThresholdStoppingCriterion(fa, STOP_FA), seeds, affine,
                                     step_size=step, max_cross=1, return_all=True))
    return streamlines, time.perf_counter() - start, peak_seconds


def polyline_distances(points, line):
    """Distance from each of `points` to the polyline `line` (its segments)."""
    if len(line) == 1:
        return np.linalg.norm(points - line[0], axis=1)
    a, b = line[:-1][None], line[1:][None]
    d = b - a
    # Where along each segment the closest point lies (a repeated point is a segment of length 0).
    along = np.einsum("psk,psk->ps", points[:, None] - a, d) / np.maximum(np.einsum("psk,psk->ps", d, d), 1e-300)
    t = np.clip(along, 0, 1)
    return np.linalg.norm(points[:, None] - (a + t[..., None] * d), axis=2).min(axis=1)


def mean_closest_point_distance(p, q):
    """Symmetrised mean closest-point distance between two polylines."""
    return 0.5 * (polyline_distances(p, q).mean() + polyline_distances(q, p).mean())


def length(line):
    return float(np.linalg.norm(np.diff(line, axis=0), axis=1).sum())


def render(output, fa, affine, seed_voxels, ours, ours_cut, theirs, title):
    """Three panels over the FA slice through the middle, with the tracts of
    the seeds in that slice projected on its plane (voxel axes i, j, in mm;
    all 595 seeds' would hide one another): riemann's (faded past FA < 0.2),
    DIPY's, and the pairs of the 12 seeds of highest FA there, one colour a
    seed (riemann's solid, cut at FA < 0.2; DIPY's dashed)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    k = fa.shape[2] // 2
    spacing = np.linalg.norm(affine[:3, :3], axis=0)
    in_slice = [s for s, v in enumerate(seed_voxels) if v[2] == k]
    traced = [s for s in in_slice if ours[s] is not None and len(theirs[s]) > 1]
    pairs = sorted(traced, key=lambda s: -fa[tuple(seed_voxels[s])])[:12]

    def plane(line):
        v = to_voxels(affine, line)
        return v[:, 0] * spacing[0], v[:, 1] * spacing[1]

    figure, axes = plt.subplots(1, 3, figsize=(15, 5.6), constrained_layout=True)
    extent = (-0.5 * spacing[0], (fa.shape[0] - 0.5) * spacing[0],
              -0.5 * spacing[1], (fa.shape[1] - 0.5) * spacing[1])
    titles = ("riemann trace: geodesics of D^-1 (faded where FA < 0.2)", "DIPY LocalTracking (EuDX, FA stop 0.2)",
              f"{len(pairs)} seeds: riemann (solid, cut) and DIPY (dashed)")
    for axis, name in zip(axes, titles):
        # imshow's rows are its vertical axis: transpose so that i runs across.
        axis.imshow(fa[:, :, k].T, origin="lower", cmap="gray", vmin=0, vmax=1, extent=extent)
        axis.set_title(name, fontsize=11)
        axis.set_xlabel("voxel axis i (mm)")
        axis.set_ylabel("voxel axis j (mm)")
        axis.set_xlim(extent[:2])
        axis.set_ylim(extent[2:])
    orange, cyan = "#ff8c1a", "#33d6ff"
    for s in in_slice:
        if ours[s] is not None:
            axes[0].plot(*plane(ours[s]), color=orange, lw=1.0, alpha=0.4)
            axes[0].plot(*plane(ours_cut[s]), color=orange, lw=1.3)
        if len(theirs[s]) > 1:
            axes[1].plot(*plane(theirs[s]), color=cyan, lw=1.3)
    colours = plt.get_cmap("tab20")
    for n, s in enumerate(pairs):
        colour = colours(n % 20)
        axes[2].plot(*plane(ours_cut[s]), color=colour, lw=1.8)
        axes[2].plot(*plane(theirs[s]), color=colour, lw=1.8, ls="--")
    centres = np.array([seed_voxels[s][:2] for s in in_slice]) * spacing[:2]
    for axis in axes[:2]:
        axis.plot(centres[:, 0], centres[:, 1], ".", color="white", ms=3)
    chosen = np.array([seed_voxels[s][:2] for s in pairs]) * spacing[:2]
    axes[2].plot(chosen[:, 0], chosen[:, 1], "o", color="white", ms=4)
    figure.suptitle(title, fontsize=11)
    figure.savefig(output, dpi=100)
    plt.close(figure)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--output", default=os.path.join(ROOT, "Documentation", "figures", "tractography-dipy.png"),
                        help="the picture (default Documentation/figures/tractography-dipy.png)")
    parser.add_argument("--workdir", default="",
                        help="keep the tensors, mask, metric and tracts here (default: a temporary folder)")
    parser.add_argument("--riemann", default=riemann_executable(),
                        help="the riemann executable (default: $RIEMANN_EXECUTABLE, else build/bin/riemann)")
    parser.add_argument("--step", type=float, default=0.5, help="step of both, mm (default 0.5)")
    parser.add_argument("--length", type=float, default=40.0,
                        help="riemann's arc length each way (default 40): mm where the tissue is "
                             "isotropic at the median diffusivity; the volume is 18 mm across, and most "
                             "tracts end at its faces")
    parser.add_argument("--repeats", type=int, default=3, help="timed runs of each, median (default 3)")
    parser.add_argument("--qform", action="store_true",
                        help="also give the tensor and mask files the scan's q-form (with the s-form "
                             "only, riemann drops some seeds of the outer voxels)")
    args = parser.parse_args()
    if not os.access(args.riemann, os.X_OK):
        sys.exit(f"tractography_dipy.py: no riemann executable at {args.riemann} (set RIEMANN_EXECUTABLE)")

    data, affine, gtab, header = load_scan()
    fit = TensorModel(gtab).fit(data)
    fa = fractional_anisotropy(fit)
    seed_mask = fa > SEED_FA
    seed_voxels = np.argwhere(seed_mask)  # seeds_from_mask's order
    seeds = seeds_from_mask(seed_mask, affine, density=1)
    print(f"small_64D: {data.shape[:3]} voxels of {np.linalg.norm(affine[:3, :3], axis=0).round(3)} mm, "
          f"{len(seeds)} seeds (FA > {SEED_FA})")

    with tempfile.TemporaryDirectory() as scratch:
        folder = args.workdir or scratch
        os.makedirs(folder, exist_ok=True)
        paths = write_inputs(folder, fit, fa, affine, header if args.qform else None)
        tracts_path = os.path.join(folder, "tracts.vtp")
        command = riemann_trace_command(args.riemann, paths["metric.json"], tracts_path,
                                        seed_mask=paths["mask.nii.gz"], step=args.step, length=args.length)
        print("$", " ".join(command))
        riemann_seconds, summary = run_riemann(command, args.repeats)
        print(summary)
        halves = riemann_halves(tracts_path, affine, seed_voxels)

    ours = [join(h) for h in halves]
    ours_cut = [join([cut_at_low_fa(half, fa, affine) for half in h]) for h in halves]
    runs = [dipy_tracts(data, fa, affine, gtab, seeds, args.step) for _ in range(args.repeats)]
    theirs = runs[0][0]
    dipy_seconds = statistics.median(r[1] for r in runs)
    peak_seconds = statistics.median(r[2] for r in runs)
    if len(theirs) != len(seeds):
        sys.exit(f"tractography_dipy.py: DIPY returned {len(theirs)} streamlines for {len(seeds)} seeds")

    ours_none = sum(t is None for t in ours)
    theirs_none = sum(len(t) < 2 for t in theirs)
    both = [s for s in range(len(seeds)) if ours[s] is not None and len(theirs[s]) > 1]
    whole = np.array([mean_closest_point_distance(ours[s], theirs[s]) for s in both])
    cut = np.array([mean_closest_point_distance(ours_cut[s], theirs[s]) for s in both])
    one_half = sum(len(h) == 1 for h in halves)
    angles = seed_angles(halves, fit, seed_voxels, affine)
    print(f"angle between riemann's first step and DIPY's e1 of the seed voxel: median {np.median(angles):.1f} deg, "
          f"90th percentile {np.percentile(angles, 90):.1f} deg")
    print(f"seeds that made no tract: riemann {ours_none} (and {one_half} with one half only), DIPY {theirs_none}")
    print(f"mean length: riemann {np.mean([length(ours[s]) for s in both]):.1f} mm "
          f"({np.mean([length(ours_cut[s]) for s in both]):.1f} mm cut at FA < {STOP_FA}), "
          f"DIPY {np.mean([length(theirs[s]) for s in both]):.1f} mm")
    print(f"mean closest-point distance over {len(both)} seeds traced by both: "
          f"{whole.mean():.2f} mm (median {np.median(whole):.2f}); "
          f"riemann cut at FA < {STOP_FA}: {cut.mean():.2f} mm (median {np.median(cut):.2f})")
    print(f"riemann trace, whole process (median of {args.repeats}): {riemann_seconds * 1e3:.1f} ms, "
          f"{len(seeds) / riemann_seconds:.0f} tracts/s")
    print(f"DIPY LocalTracking loop (median of {args.repeats}): {dipy_seconds * 1e3:.1f} ms, "
          f"{len(seeds) / dipy_seconds:.0f} tracts/s (its peaks_from_model: {peak_seconds * 1e3:.0f} ms more)")

    try:
        title = (f"DIPY's small_64D, {len(seeds)} seeds (FA > {SEED_FA}), step {args.step} mm; the seeds of "
                 f"slice k = {fa.shape[2] // 2} shown; mean closest-point distance "
                 f"{cut.mean():.2f} mm (riemann cut at FA < {STOP_FA}), {whole.mean():.2f} mm (whole)")
        os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
        render(args.output, fa, affine, seed_voxels, ours, ours_cut, theirs, title)
        print("wrote", args.output)
    except ImportError:
        print("no picture: matplotlib is not installed")


if __name__ == "__main__":
    main()
