#!/usr/bin/python3
"""riemann trace against MRtrix3's tckgen (Tensor_Det) and DIPY, in one run.

Same scan, same seeds, same stops: DIPY's small_64D (10^3 voxels of 2 mm, 64
directions at b = 1000), seeds where DIPY's FA > 0.3, every tracker traced
both ways from each seed at step 0.5 mm and stopped where the FA falls
below 0.2, one tract a seed, no angle limit, no minimum length:

- riemann: `riemann trace --seed-mask` on the geodesics of each tensor
  metric (inverse, adjugate, sharpened) of the tensors DIPY fits (written
  as dipy_fit_dti writes them, "frame": "fsl") and of those MRtrix's
  dwi2tensor fits (`mrconvert dt.mif dt.nii.gz`, "components": "mrtrix"),
  each with the spline's Christoffel symbols and the voxels' (--christoffel);
- MRtrix3: `tckgen -algorithm Tensor_Det` on the DWI itself (its tensor
  fitted at each step from the trilinearly interpolated signal), seeds
  `-seed_grid_per_voxel mask 1` (the voxel centres), `-cutoff 0.2`,
  `-angle 90`, `-minlength 0`;
- DIPY: LocalTracking with EuDX's direction getter on the tensor's peak,
  ThresholdStoppingCriterion on the FA (Examples/tractography_dipy.py).

With `--density 3`, 27 seeds a voxel: MRtrix's `-seed_grid_per_voxel mask 3`
(a 3 x 3 x 3 grid in each voxel), riemann's `--seed-mask` of a mask three
times finer whose voxel centres are that grid, DIPY's seeds_from_mask
density 3 (the same grid).

Printed per tracker: seeds, tracts, tracts per wall-second and per
CPU-second (the whole process's user + system time, start-up and files
included; DIPY's loop alone, its peaks not counted), on 1 thread and on 2
(riemann: VTK_SMP_MAX_THREADS; tckgen: -nthreads 0 and 2); then, over the
seeds traced by both, the mean closest-point distance (symmetrised) of
each tracker's tracts to Tensor_Det's, with the mean lengths.

Run: RIEMANN_EXECUTABLE=build/bin/riemann /usr/bin/python3 Testing/Benchmarks/tractography_vs_mrtrix.py \
       [--density 1] [--runs 3]
Needs DIPY, nibabel and MRtrix3 (python3-dipy, python3-nibabel, mrtrix3,
which run.sh installs for this benchmark only); without them it says so and
exits 0.
"""
import argparse
import json
import os
import resource
import shutil
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
    print(f"tractography_vs_mrtrix.py: skipped: needs DIPY and nibabel ({missing})")
    sys.exit(0)
if not shutil.which("tckgen"):
    print("tractography_vs_mrtrix.py: skipped: needs MRtrix3's tckgen (apt-get install mrtrix3)")
    sys.exit(0)
import tractography_dipy as example  # noqa: E402

from dipy.tracking.utils import seeds_from_mask  # noqa: E402

STEP = 0.5
LENGTH = 80.0


def timed(command, runs, env=None):
    """Median wall seconds and CPU seconds (user + system of the child) of `runs` runs."""
    walls, cpus = [], []
    for _ in range(runs):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        done = subprocess.run(command, capture_output=True, text=True, env=env)
        walls.append(time.perf_counter() - start)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpus.append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
        if done.returncode != 0:
            sys.exit(f"tractography_vs_mrtrix.py: {' '.join(command)} failed:\n{done.stderr}")
    return statistics.median(walls), statistics.median(cpus)


def write_fsl_gradients(folder, gtab):
    """bvecs (3 rows) and bvals as FSL writes them, for MRtrix's -fslgrad."""
    bvecs, bvals = os.path.join(folder, "bvecs"), os.path.join(folder, "bvals")
    np.savetxt(bvecs, np.nan_to_num(gtab.bvecs).T, fmt="%.10f")
    np.savetxt(bvals, gtab.bvals[None], fmt="%.4f")
    return bvecs, bvals


def mrtrix_tensors(folder, dwi, grad):
    """dwi2tensor's tensors as a NIfTI (mrconvert dt.mif dt.nii.gz) and a metric of them."""
    mif, nii = os.path.join(folder, "dt.mif"), os.path.join(folder, "dt.nii.gz")
    subprocess.run(["dwi2tensor", "-quiet", "-force", "-fslgrad", *grad, dwi, mif], check=True)
    subprocess.run(["mrconvert", "-quiet", "-force", mif, nii], check=True)
    return nii


def write_metric(path, tensors, tensor_metric, christoffel, mrtrix):
    metric = {"type": "sampled", "file": os.path.basename(tensors), "tensor_metric": tensor_metric,
              "scale": "mean-diffusivity", "outside": "stop", "repair": "clamp",
              "christoffel": christoffel}
    metric.update({"components": "mrtrix"} if mrtrix else {"frame": "fsl"})
    with open(path, "w") as f:
        json.dump(metric, f)
    return path


def finer_mask(mask, affine, density):
    """A mask `density` times finer on each axis whose voxel centres are the
    density^3 grid of each voxel of `mask` (MRtrix's -seed_grid_per_voxel)."""
    fine = np.repeat(np.repeat(np.repeat(mask, density, 0), density, 1), density, 2)
    scale = np.diag([1.0 / density] * 3 + [1.0])
    shift = np.eye(4)
    shift[:3, 3] = -0.5 + 0.5 / density
    return fine, affine @ shift @ scale


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--density", type=int, default=1, help="seeds per voxel per axis (default 1)")
    parser.add_argument("--runs", type=int, default=3, help="timed runs of each, median (default 3)")
    parser.add_argument("--workdir", default="", help="keep the files here (default: a temporary folder)")
    args = parser.parse_args()
    riemann = example.riemann_executable()

    data, affine, gtab, _ = example.load_scan()
    fit = example.TensorModel(gtab).fit(data)
    fa = example.fractional_anisotropy(fit)
    mask = fa > example.SEED_FA
    with tempfile.TemporaryDirectory() as scratch:
        folder = args.workdir or scratch
        os.makedirs(folder, exist_ok=True)
        paths = example.write_inputs(folder, fit, fa, affine)
        dwi, _, _ = example.get_fnames("small_64D")
        grad = write_fsl_gradients(folder, gtab)
        mrtrix_nii = mrtrix_tensors(folder, dwi, grad)
        fine, fine_affine = finer_mask(mask, affine, args.density)
        seed_mask = os.path.join(folder, "seeds.nii.gz")
        nib.save(nib.Nifti1Image(fine.astype(np.uint8), fine_affine), seed_mask)
        seed_voxels = np.argwhere(fine)
        seeds = seeds_from_mask(mask, affine, density=args.density)
        print(f"small_64D: {data.shape[:3]} voxels of 2 mm, {len(seed_voxels)} seeds "
              f"({args.density ** 3} a voxel where FA > {example.SEED_FA}), step {STEP} mm, stop FA < {example.STOP_FA}")

        rows, tracts = [], {}
        # MRtrix3 Tensor_Det.
        tck = os.path.join(folder, "tensor_det.tck")
        for threads in (0, 2):
            command = ["tckgen", "-quiet", "-force", "-algorithm", "Tensor_Det", dwi, tck, "-fslgrad", *grad,
                       "-seed_grid_per_voxel", os.path.join(folder, "mask.nii.gz"), str(args.density),
                       "-select", "0", "-step", str(STEP), "-cutoff", str(example.STOP_FA),
                       "-seed_cutoff", str(example.STOP_FA), "-angle", "90", "-minlength", "0",
                       "-maxlength", str(LENGTH), "-nthreads", str(threads)]
            wall, cpu = timed(command, args.runs)
            rows.append(("tckgen Tensor_Det", max(threads, 1), wall, cpu))
        tracts["tckgen"] = example.match_seeds(example.read_tracts(tck)[0], fine_affine, seed_voxels)

        # riemann: every tensor metric, both readings, both fits.
        for fitter, tensors in (("DIPY", paths["tensors.nii.gz"]), ("MRtrix", mrtrix_nii)):
            for tensor_metric in example.TENSOR_METRICS:
                for christoffel in ("spline", "voxels"):
                    name = f"riemann {tensor_metric} {christoffel} ({fitter} fit)"
                    metric = write_metric(os.path.join(os.path.dirname(tensors), "m.json"), tensors,
                                          tensor_metric, christoffel, fitter == "MRtrix")
                    trk = os.path.join(folder, "riemann.tck")
                    command = example.riemann_trace_command(riemann, metric, trk, seed_mask=seed_mask,
                                                            step=STEP, length=LENGTH)
                    for threads in (1, 2):
                        env = dict(os.environ, VTK_SMP_MAX_THREADS=str(threads))
                        wall, cpu = timed(command, args.runs, env)
                        rows.append((name, threads, wall, cpu))
                    tracts[name] = example.match_seeds(example.read_tracts(trk)[0], fine_affine, seed_voxels)

        # DIPY.
        runs = [example.dipy_tracts(data, fa, affine, gtab, seeds, STEP) for _ in range(args.runs)]
        dipy_wall = statistics.median(r[1] for r in runs)
        rows.append(("DIPY LocalTracking (loop)", 1, dipy_wall, dipy_wall))
        # Matched by position as the others (seeds_from_mask orders a
        # voxel's grid otherwise); a seed DIPY took no step from has one point.
        tracts["DIPY LocalTracking"] = example.match_seeds(
            [line for line in runs[0][0] if len(line) > 1], fine_affine, seed_voxels)

    print(f"{'tracker':44s} {'threads':>7s} {'wall s':>8s} {'CPU s':>8s} {'tracts/wall-s':>14s} "
          f"{'tracts/CPU-s':>13s}")
    for name, threads, wall, cpu in rows:
        print(f"{name:44s} {threads:7d} {wall:8.3f} {cpu:8.3f} {len(seed_voxels) / wall:14,.0f} "
              f"{len(seed_voxels) / cpu:13,.0f}")
    riemann_rows = {(n, t): w for n, t, w, _ in rows}
    print("2 threads over 1 (wall):", ", ".join(
        f"{n.split(' (')[0].replace('riemann ', '')} {'DIPY' if 'DIPY' in n else 'MRtrix'} "
        f"{riemann_rows[n, 1] / riemann_rows[n, 2]:.2f}"
        for n, t in riemann_rows if t == 1 and (n, 2) in riemann_rows))

    reference = [m[0] if m is not None else None for m in tracts["tckgen"]]
    print(f"Tensor_Det traced {sum(r is not None for r in reference)} of {len(seed_voxels)} seeds")
    print("mean closest-point distance to Tensor_Det's tract of the same seed (seeds traced by both):")
    ours = {n: [m[0] if m is not None else None for m in t] for n, t in tracts.items() if n != "tckgen"}
    for name, lines in ours.items():
        both = [s for s in range(len(seed_voxels)) if reference[s] is not None and lines[s] is not None
                and len(lines[s]) > 1]
        distances = np.array([example.mean_closest_point_distance(lines[s], reference[s]) for s in both])
        print(f"  {name:44s} {len(both):6d} seeds: {distances.mean():.2f} mm (median {np.median(distances):.2f}); "
              f"length {np.mean([example.length(lines[s]) for s in both]):.1f} mm against "
              f"{np.mean([example.length(reference[s]) for s in both]):.1f}")


if __name__ == "__main__":
    main()
