#!/usr/bin/python3
"""Geodesic tractography of a diffusion scan no one here made, against DIPY.

    tractography_dipy.py [--output Documentation/figures/tractography-dipy.png]
                         [--workdir DIR] [--step 0.5] [--length 40] [--repeats 3]
                         [--riemann build/bin/riemann]

The scan is DIPY's `small_64D` (dipy.data.get_fnames: 10^3 voxels of 2 mm,
one b0 and 64 directions at b = 1000, an oblique affine). DIPY fits the
tensors (dipy.reconst.dti.TensorModel) and they are saved as DIPY's
`dipy_fit_dti` saves them (dipy.io.utils.nifti1_symmat: the six lower-
triangular components, intent NIFTI_INTENT_SYMMATRIX, placed by the s-form
only, qfac -1). The metric is their inverse, in FSL's voxel frame, as DIPY
fits them with FSL-style bvecs (Documentation/MetricFormat.md, "sampled"):

    {"type": "sampled", "file": "tensors.nii.gz", "tensor_metric": "inverse",
     "scale": "mean-diffusivity", "outside": "stop", "repair": "clamp",
     "frame": "fsl"}

Seeds: every voxel with FA > 0.3 (a NIfTI mask with the scan's affine), at
its centre (595). Both stop where the FA falls below 0.2: riemann with
`--stop-fa 0.2` (the FA of the tensor the metric stands for, read from the
metric's spline), DIPY with ThresholdStoppingCriterion (the fitted FA map,
trilinear). `riemann trace --seed-mask` follows the geodesics both ways
along each seed's e1 and writes them as TrackVis .trk (one streamline a
seed, both halves joined, in RAS+ mm against the tensors' grid), which
nibabel.streamlines.load reads back here as it reads DIPY's own; DIPY's
deterministic LocalTracking follows the tensor's peak (peaks_from_model,
EuDX's direction getter) from the same seeds (seeds_from_mask, density 1).
--length and --step are riemann's arc length, which is mm only where the
tissue is isotropic at the scan's median diffusivity: a mm along a fibre is
less arc length, a mm across one (or through a nearly degenerate tensor)
more.

A .trk holds no seed numbers, and a seed whose geodesics made nothing has
no streamline, so each streamline is matched to its seed by position: the
tracer starts at the seed voxel's centre and writes that point (to float32
rounding, 1e-6 voxel here); no other point of a tract falls within 1e-3
voxel of a seed centre but by chance, and a tract that did would be given
the seed no other tract has (match_seeds).

Printed, as measured with riemann 697678a and DIPY 1.6 on 2 idle cores
(the timings vary with the machine's load): 595 seeds; riemann's summary
(1,174 geodesics, 22,227 points: 1,023 halves left the volume, 105 fell
below FA 0.2, 46 reached --length; 8 seeds made none: the FA of the metric's
cubic B-spline, which blends each voxel's D^-1 with its neighbours', is
below 0.2 at their centres, though above 0.3 in the voxel); the angle
between riemann's first step and the seed voxel's e1 (median 8.0 deg, 90th
percentile 30.9: a check of the frame); the seeds that made no tract,
riemann 8, DIPY 152 (all in the outer layer of voxels: every seed of the
faces i = 0, j = 9 and k = 9, some of the others, where DIPY takes no
step); the mean length over the 437 seeds both traced, riemann 16.5 mm,
DIPY 12.6 mm (the spline's FA at the seeds is higher than the voxels',
median 0.55 against 0.49, so riemann stops later; most of its tracts end
at the volume's faces); the mean closest-point distance between the two
tracts of a seed (symmetrised: the mean over each tract's points of the
distance to the other tract, averaged both ways), 1.70 mm (median 1.35);
then the same for each tensor metric, the same seeds and stops:

    tensor_metric  g                    seeds traced  distance to DIPY    length
    inverse        D^-1                 587 (437)     1.70 mm (med 1.35)  16.5 mm
    adjugate       det(D) D^-1          524 (398)     1.55 mm (med 1.32)  11.8 mm
    sharpened      det(D)^(1/3) D^-2    590 (440)     1.72 mm (med 1.33)  17.5 mm

(in brackets, the seeds DIPY traced too, over which the distance and the
mean length are taken). Not a ranking: the spline blends the metric, not
D, and the blend of the adjugate, which weighs each voxel by det D, is
dominated by the nearly isotropic voxels of high diffusivity, so the FA
that --stop-fa reads is lower (median 0.31 at the seeds): 71 seeds make no
tract and the tracts are shorter, hence closer to DIPY's. Last, the tracts
per second of each on this machine: riemann trace 10,500 (the whole
process, start-up and the .trk included: 57 ms; adjugate 15,300 and
sharpened 9,500), DIPY's LocalTracking 76,000 (its loop alone, 7.8 ms;
its peaks_from_model takes 550 ms more). At 595 seeds riemann's start-up
dominates: see Testing/Benchmarks/tractography_vs_dipy.py for more seeds.

The picture: over the FA of the middle slice (k = 5), the tracts of its
seeds, riemann's (orange) and DIPY's (cyan), and the pairs of its 12 seeds
of highest FA, one colour a seed, in the slice's voxel plane (mm).

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
TENSOR_METRICS = ("inverse", "adjugate", "sharpened")


def riemann_executable():
    return os.environ.get("RIEMANN_EXECUTABLE", os.path.join(ROOT, "build", "bin", "riemann"))


def riemann_trace_command(riemann, metric, output, *, step, length, seed_mask=None, seeds=None,
                          seeds_per_voxel=1, propagation="both", stop_fa=STOP_FA):
    """The `riemann trace` command line: seeds from a mask (each voxel's
    centre, along e1) or a file of seeds (a CSV of points and directions),
    traced both ways, stopped where the FA is below `stop_fa` (0: no stop).
    `output` ends in .trk, .tck, .vtp or .csv."""
    command = [riemann, "trace", "-m", metric, "--propagation", propagation,
               "--step", repr(float(step)), "--length", repr(float(length)), "-o", output]
    if stop_fa:
        command += ["--stop-fa", repr(float(stop_fa))]
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


def write_metric(path, tensor_metric="inverse"):
    """A sampled metric of tensors.nii.gz (next to `path`)."""
    metric = {"type": "sampled", "file": "tensors.nii.gz", "tensor_metric": tensor_metric,
              # Steps and lengths in mm where the tissue is isotropic, whatever
              # the tensors' units (DIPY's are mm^2/s) and the tensor metric.
              "scale": "mean-diffusivity",
              "outside": "stop",
              # Fitted tensors of noisy voxels can have eigenvalues <= 0.
              "repair": "clamp",
              # DIPY's tensors are in the frame of FSL-style bvecs.
              "frame": "fsl"}
    with open(path, "w") as f:
        json.dump(metric, f, indent=1)
    return path


def write_inputs(folder, fit, fa, affine):
    """tensors.nii.gz (as DIPY saves them: s-form only), mask.nii.gz
    (FA > SEED_FA, as nibabel saves it) and metric.json (D^-1) in
    `folder`; their paths."""
    tensors = nifti1_symmat(lower_triangular(fit.quadratic_form).astype(np.float32), affine)
    mask = nib.Nifti1Image((fa > SEED_FA).astype(np.uint8), affine)
    paths = {name: os.path.join(folder, name) for name in ("tensors.nii.gz", "mask.nii.gz", "metric.json")}
    nib.save(tensors, paths["tensors.nii.gz"])
    nib.save(mask, paths["mask.nii.gz"])
    write_metric(paths["metric.json"])
    return paths


def to_voxels(affine, points):
    inverse = np.linalg.inv(affine)
    return points @ inverse[:3, :3].T + inverse[:3, 3]


def read_tracts(path):
    """The streamlines of a .trk or .tck, as DIPY users read them (RAS+ mm),
    and the file's voxel-to-RAS affine (for a .trk, that of its reference)."""
    tractogram = nib.streamlines.load(path)
    return [np.asarray(s, dtype=float) for s in tractogram.streamlines], tractogram.affine


def match_seeds(tracts, affine, seed_voxels, tolerance=1e-3):
    """Per seed of `seed_voxels` (voxel indices, DIPY's seed order): (its
    tract, the index of the seed point in it), or None where it has none.
    A tract's seed is the seed voxel whose centre is one of its points (to
    `tolerance` voxel). Another point of a tract lands on a seed centre only
    by chance; a tract with several is given, once the tracts with one are
    matched, the seed no other tract has."""
    index = {tuple(v): s for s, v in enumerate(seed_voxels)}
    candidates = []
    for tract in tracts:
        voxels = to_voxels(affine, tract)
        nearest = np.rint(voxels)
        on_centre = np.nonzero(np.abs(voxels - nearest).max(axis=1) < tolerance)[0]
        found = [(index[key], p) for p in on_centre if (key := tuple(nearest[p].astype(int))) in index]
        if not found:
            sys.exit("tractography_dipy.py: a streamline passes through no seed's centre")
        candidates.append(found)
    matched = [None] * len(seed_voxels)
    pending = list(range(len(tracts)))
    while pending:
        left = []
        for t in pending:
            free = [(s, p) for s, p in candidates[t] if matched[s] is None]
            if len(free) == 1:
                matched[free[0][0]] = (tracts[t], free[0][1])
            elif not free:
                sys.exit("tractography_dipy.py: two streamlines start at the same seed")
            else:
                left.append(t)
        if len(left) == len(pending):
            sys.exit(f"tractography_dipy.py: {len(left)} streamlines pass through several seeds' centres")
        pending = left
    return matched


def seed_angles(matched, fit, seed_voxels, affine):
    """Per traced seed, the angle (degrees) between riemann's first step and
    the seed voxel's e1 as DIPY fitted it, turned to world axes: a check of
    the frame ("fsl"). Not 0: riemann's g is a B-spline, which blends each
    sample with its neighbours' (MetricFormat.md), and this scan is noisy."""
    axes = affine[:3, :3] / np.linalg.norm(affine[:3, :3], axis=0)
    angles = []
    for m, voxel in zip(matched, seed_voxels):
        if m is not None:
            tract, p = m
            step = tract[p + 1] - tract[p] if p + 1 < len(tract) else tract[p - 1] - tract[p]
            e1 = axes @ fit.evecs[tuple(voxel)][:, 0]
            angles.append(np.degrees(np.arccos(min(1.0, abs(float(step @ e1) / np.linalg.norm(step))))))
    return np.array(angles)


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


def compare(ours, theirs):
    """Against DIPY, over the seeds both traced: (those seeds, the mean
    closest-point distance of each, riemann's lengths, DIPY's lengths)."""
    both = [s for s in range(len(theirs)) if ours[s] is not None and len(theirs[s]) > 1]
    distances = np.array([mean_closest_point_distance(ours[s], theirs[s]) for s in both])
    return (both, distances, np.array([length(ours[s]) for s in both]),
            np.array([length(theirs[s]) for s in both]))


def render(output, fa, affine, seed_voxels, ours, theirs, title):
    """Three panels over the FA slice through the middle, with the tracts of
    the seeds in that slice projected on its plane (voxel axes i, j, in mm;
    all 595 seeds' would hide one another): riemann's, DIPY's, and the pairs
    of the 12 seeds of highest FA there, one colour a seed (riemann's solid,
    DIPY's dashed)."""
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
    titles = (f"riemann trace --stop-fa {STOP_FA}: geodesics of D^-1", f"DIPY LocalTracking (EuDX, FA stop {STOP_FA})",
              f"{len(pairs)} seeds: riemann (solid) and DIPY (dashed)")
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
            axes[0].plot(*plane(ours[s]), color=orange, lw=1.3)
        if len(theirs[s]) > 1:
            axes[1].plot(*plane(theirs[s]), color=cyan, lw=1.3)
    colours = plt.get_cmap("tab20")
    for n, s in enumerate(pairs):
        colour = colours(n % 20)
        axes[2].plot(*plane(ours[s]), color=colour, lw=1.8)
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
                        help="keep the tensors, mask, metrics and tracts here (default: a temporary folder)")
    parser.add_argument("--riemann", default=riemann_executable(),
                        help="the riemann executable (default: $RIEMANN_EXECUTABLE, else build/bin/riemann)")
    parser.add_argument("--step", type=float, default=0.5, help="step of both, mm (default 0.5)")
    parser.add_argument("--length", type=float, default=40.0,
                        help="riemann's arc length each way (default 40): mm where the tissue is "
                             "isotropic at the median diffusivity; the voxel centres span 18 mm, and most "
                             "tracts end at the volume's faces or where the FA falls below 0.2")
    parser.add_argument("--repeats", type=int, default=3, help="timed runs of each, median (default 3)")
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

    runs = [dipy_tracts(data, fa, affine, gtab, seeds, args.step) for _ in range(args.repeats)]
    theirs = runs[0][0]
    dipy_seconds = statistics.median(r[1] for r in runs)
    peak_seconds = statistics.median(r[2] for r in runs)
    if len(theirs) != len(seeds):
        sys.exit(f"tractography_dipy.py: DIPY returned {len(theirs)} streamlines for {len(seeds)} seeds")

    ours, seconds, counts = {}, {}, {}
    with tempfile.TemporaryDirectory() as scratch:
        folder = args.workdir or scratch
        os.makedirs(folder, exist_ok=True)
        paths = write_inputs(folder, fit, fa, affine)
        for tensor_metric in TENSOR_METRICS:
            metric = paths["metric.json"] if tensor_metric == "inverse" else \
                write_metric(os.path.join(folder, f"metric-{tensor_metric}.json"), tensor_metric)
            tracts_path = os.path.join(folder, f"tracts-{tensor_metric}.trk")
            command = riemann_trace_command(args.riemann, metric, tracts_path, seed_mask=paths["mask.nii.gz"],
                                            step=args.step, length=args.length)
            seconds[tensor_metric], summary = run_riemann(command, args.repeats)
            # What a DIPY user does with the file: nibabel puts the points in RAS+ mm.
            tracts, trk_affine = read_tracts(tracts_path)
            if tensor_metric == "inverse":
                print("$", " ".join(command))
                print(summary)
                print(f"{tracts_path}: {len(tracts)} streamlines; its voxel-to-RAS affine is the scan's to "
                      f"{np.abs(trk_affine - affine).max():.1e} mm")
            counts[tensor_metric] = len(tracts)
            ours[tensor_metric] = match_seeds(tracts, affine, seed_voxels)

    matched = ours["inverse"]
    tracts = [m[0] if m is not None else None for m in matched]
    angles = seed_angles(matched, fit, seed_voxels, affine)
    one_half = sum(m is not None and (m[1] == 0 or m[1] == len(m[0]) - 1) for m in matched)
    both, distances, our_lengths, their_lengths = compare(tracts, theirs)
    print(f"angle between riemann's first step and DIPY's e1 of the seed voxel: median {np.median(angles):.1f} deg, "
          f"90th percentile {np.percentile(angles, 90):.1f} deg")
    print(f"seeds that made no tract: riemann {sum(t is None for t in tracts)} (and {one_half} with one half only), "
          f"DIPY {sum(len(t) < 2 for t in theirs)}")
    print(f"mean length over the {len(both)} seeds traced by both: riemann {our_lengths.mean():.1f} mm, "
          f"DIPY {their_lengths.mean():.1f} mm")
    print(f"mean closest-point distance over them: {distances.mean():.2f} mm (median {np.median(distances):.2f})")
    print(f"tensor metrics against DIPY (same seeds, both stopped at FA < {STOP_FA}; seeds traced by both; "
          "mean closest-point distance, median; riemann's mean length; riemann tracts/s):")
    results = {}
    for tensor_metric in TENSOR_METRICS:
        t = [m[0] if m is not None else None for m in ours[tensor_metric]]
        b, d, lengths, _ = compare(t, theirs)
        results[tensor_metric] = d.mean()
        print(f"  {tensor_metric:9s} {len(b)} seeds ({len(seeds) - counts[tensor_metric]} untraced): "
              f"{d.mean():.2f} mm (median {np.median(d):.2f}), {lengths.mean():.1f} mm long, "
              f"{len(seeds) / seconds[tensor_metric]:,.0f} tracts/s")
    print(f"riemann trace --stop-fa {STOP_FA}, whole process (median of {args.repeats}): "
          f"{seconds['inverse'] * 1e3:.1f} ms, {len(seeds) / seconds['inverse']:,.0f} tracts/s")
    print(f"DIPY LocalTracking loop (median of {args.repeats}): {dipy_seconds * 1e3:.1f} ms, "
          f"{len(seeds) / dipy_seconds:,.0f} tracts/s (its peaks_from_model: {peak_seconds * 1e3:.0f} ms more)")

    try:
        title = (f"DIPY's small_64D, {len(seeds)} seeds (FA > {SEED_FA}), step {args.step} mm, both stop at "
                 f"FA < {STOP_FA}; the seeds of slice k = {fa.shape[2] // 2} shown. Mean closest-point distance "
                 f"to DIPY: D^-1 {results['inverse']:.2f} mm, adjugate {results['adjugate']:.2f}, "
                 f"sharpened {results['sharpened']:.2f}")
        os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
        render(args.output, fa, affine, seed_voxels, tracts, theirs, title)
        print("wrote", args.output)
    except ImportError:
        print("no picture: matplotlib is not installed")


if __name__ == "__main__":
    main()
