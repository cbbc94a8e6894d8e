#!/usr/bin/env python3
"""A curvature volume and a fan of geodesics computed by several MPI ranks.

    mpirun -np 4 /usr/bin/python3 distributed_fields.py [--metric M.json]
           [--dimensions 64] [--geodesics 200] [--output-dir out]

Every rank runs the same pipeline and asks it for its own piece (piece =
rank, number of pieces = ranks), as ParaView's pvbatch does: the curvature
field computes only its part of the grid (vtkExtentTranslator's split of
the whole extent) and the geodesic tracer only its share of the seeds. VTK's
parallel XML writers, given the MPI controller, write one piece file per
rank and rank 0 the summary files readable by ParaView and by VTK's parallel
readers:

    out/curvature.pvti   (+ curvature_<rank>.vti)
    out/geodesics.pvtp   (+ geodesics_<rank>.vtp)

The result is the same, bitwise, as one process computing everything. As
root, Open MPI wants `mpirun --allow-run-as-root`; with more ranks than
cores, `--oversubscribe`. mpi4py initialises MPI (it must be imported before
the controller is made). Run with ./run.sh's environment
(PYTHONPATH=build/lib/python3/dist-packages).
"""
import argparse
import os
import sys

from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkIOParallelXML import vtkXMLPImageDataWriter, vtkXMLPPolyDataWriter
from vtkmodules.vtkParallelCore import vtkMultiProcessController
from vtkmodules.vtkParallelMPI import vtkMPIController

import riemann


def seeds(count):
    """Seeds on a line at x = -2.5, heading through the metric's bumps."""
    points = vtkPoints()
    directions = vtkDoubleArray()
    directions.SetName("Direction")
    directions.SetNumberOfComponents(3)
    for i in range(count):
        a = -1.0 + 2.0 * i / max(1, count - 1)
        points.InsertNextPoint(-2.5, 1.5 * a, 0.3 * a)
        directions.InsertNextTuple3(1.0, -0.2 * a, 0.05)
    data = vtkPolyData()
    data.SetPoints(points)
    data.GetPointData().AddArray(directions)
    return data


def write(writer, controller, algorithm, path):
    """Each rank writes its piece; rank 0 also the summary file."""
    rank = controller.GetLocalProcessId()
    ranks = controller.GetNumberOfProcesses()
    writer.SetController(controller)
    writer.SetInputConnection(algorithm.GetOutputPort())
    writer.SetFileName(path)
    writer.SetNumberOfPieces(ranks)
    writer.SetStartPiece(rank)
    writer.SetEndPiece(rank)
    writer.SetCompressorTypeToLZ4()
    if not writer.Write():
        raise RuntimeError(f"rank {rank}: cannot write {path}")


def main():
    data = os.environ.get("RIEMANN_DATA_DIR", os.path.join(os.path.dirname(__file__), "..", "Data"))
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--metric", default=os.path.join(data, "metrics", "two-bumps.json"))
    parser.add_argument("--dimensions", type=int, default=64, help="grid points per axis")
    parser.add_argument("--geodesics", type=int, default=200)
    parser.add_argument("--output-dir", default="out")
    args = parser.parse_args()

    # mpi4py initialises MPI; VTK's controller then uses it. (Imported here,
    # not at the top, so that importing this file for seeds() starts no MPI.)
    from mpi4py import MPI  # noqa: F401

    controller = vtkMPIController()
    controller.Initialize()
    vtkMultiProcessController.SetGlobalController(controller)
    rank = controller.GetLocalProcessId()
    ranks = controller.GetNumberOfProcesses()

    # Every rank checks the same metric: they fail or succeed together, so no
    # rank waits for another in the writers' collective steps.
    metric = riemann.vtkRiemannMetric()
    if not metric.SetDefinitionFile(args.metric):
        if rank == 0:
            print("distributed_fields: " + metric.GetLastError(), file=sys.stderr)
        controller.Finalize(1)
        sys.exit(1)
    if rank == 0:
        os.makedirs(args.output_dir, exist_ok=True)
    controller.Barrier()

    field = riemann.vtkRiemannCurvatureField()
    field.SetMetric(metric)
    field.SetBounds(-2, 2, -2, 2, -2, 2)
    n = args.dimensions
    field.SetDimensions(n, n, n)
    write(vtkXMLPImageDataWriter(), controller, field, os.path.join(args.output_dir, "curvature.pvti"))

    tracer = riemann.vtkRiemannGeodesicTracer()
    tracer.SetMetric(metric)
    tracer.SetInputData(seeds(args.geodesics))
    tracer.GetIntegrationSettings().SetMaximumPropagation(6.0)
    write(vtkXMLPPolyDataWriter(), controller, tracer, os.path.join(args.output_dir, "geodesics.pvtp"))

    points = field.GetOutput().GetNumberOfPoints()
    lines = tracer.GetOutput().GetNumberOfLines()
    print(f"rank {rank} of {ranks}: {points} grid points, {lines} geodesics")
    controller.Finalize(1)


if __name__ == "__main__":
    main()
