#!/usr/bin/env python3
"""Write fibre-phantom.vti: a synthetic diffusion-tensor volume (issue 17).

    /usr/bin/python3 Data/phantom/make_fibre_phantom.py [output.vti]

Three bundles of parallel fibres in an isotropic background, on a
40 x 40 x 24 grid of spacing 0.1 (the box [-1.95, 1.95] x [-1.95, 1.95] x
[-1.15, 1.15]; lengths in arbitrary units, diffusivities in 1e-3 mm^2/s):

- "x bundle": a tube of radius 0.3 around the x axis at y = 0, z = -0.35;
- "y bundle": a tube of radius 0.3 around the y axis at x = 0, z = -0.35,
  crossing the x bundle at (0, 0, -0.35);
- "arc bundle": a tube of radius 0.3 around the half circle of radius 1.2
  about the origin in the plane z = 0.45, y >= 0 (its fibres run along the
  circle, direction (-y, x, 0) / r);

Inside a bundle of direction t the tensor is D = 1.7 t t^T + 0.3 (I - t t^T)
(fractional anisotropy 0.80, as in white matter); the background is 0.8 I.
Where bundles meet, and at their soft edges, the tensors are blended by
weight: D = (1 - sum w_i) 0.8 I + sum w_i D_i with w_i = smoothstep of the
distance to the bundle's axis (1 inside radius 0.2, 0 beyond 0.4), the
weights scaled down where they sum past 1. The crossing is therefore an
oblate tensor, as partial volumes of two bundles are in real data.

Arrays (point data):
- "Tensors": D, 6 components in VTK's order (XX, YY, ZZ, XY, YZ, XZ);
- "FractionalAnisotropy": FA of D;
- "FibreDirection": the direction t of the bundle of largest weight (zero in
  the background), and "Bundle": its number (0 none, 1 x, 2 y, 3 arc), for
  measuring how well tracts follow the fibres.

The metric for geodesic tractography is g = D^-1 (`"inverse": true`):
moving along a fibre is cheap, so geodesics run along the bundles.
"""
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter

DIMENSIONS = (40, 40, 24)
SPACING = 0.1
PARALLEL, PERPENDICULAR, BACKGROUND = 1.7, 0.2, 0.8
INNER, OUTER = 0.2, 0.4
ARC_RADIUS, ARC_Z, CROSS_Z = 1.5, 0.45, -0.35


def smoothstep_weight(distance):
    """1 inside INNER, 0 beyond OUTER, C1 in between."""
    s = np.clip((OUTER - distance) / (OUTER - INNER), 0.0, 1.0)
    return s * s * (3.0 - 2.0 * s)


def bundles(x, y, z):
    """Per bundle: (weight, unit direction field) at the points."""
    ones, zeros = np.ones_like(x), np.zeros_like(x)
    along_x = smoothstep_weight(np.hypot(y, z - CROSS_Z)), np.stack([ones, zeros, zeros], -1)
    along_y = smoothstep_weight(np.hypot(x, z - CROSS_Z)), np.stack([zeros, ones, zeros], -1)
    r = np.hypot(x, y)
    arc_distance = np.where(y >= 0.0, np.hypot(r - ARC_RADIUS, z - ARC_Z),
                            np.hypot(np.hypot(np.abs(x) - ARC_RADIUS, y), z - ARC_Z))
    safe_r = np.where(r > 1e-9, r, 1.0)
    tangent = np.stack([-y / safe_r, x / safe_r, zeros], -1)
    tangent = np.where((y >= 0.0)[..., None], tangent, np.stack([zeros, np.sign(x), zeros], -1))
    arc = smoothstep_weight(arc_distance), tangent
    return [along_x, along_y, arc]


def phantom():
    nx, ny, nz = DIMENSIONS
    origin = -0.5 * SPACING * (np.array(DIMENSIONS) - 1)
    z, y, x = np.meshgrid(origin[2] + SPACING * np.arange(nz), origin[1] + SPACING * np.arange(ny),
                          origin[0] + SPACING * np.arange(nx), indexing="ij")
    parts = bundles(x, y, z)
    weights = np.stack([w for w, _ in parts], -1)
    total = weights.sum(-1)
    weights = weights / np.maximum(total, 1.0)[..., None]
    identity = np.eye(3)
    d = (1.0 - weights.sum(-1))[..., None, None] * BACKGROUND * identity
    for i, (_, t) in enumerate(parts):
        tt = t[..., :, None] * t[..., None, :]
        d = d + weights[..., i, None, None] * (PARALLEL * tt + PERPENDICULAR * (identity - tt))
    eigen = np.linalg.eigvalsh(d)
    mean = eigen.mean(-1, keepdims=True)
    fa = np.sqrt(1.5 * ((eigen - mean) ** 2).sum(-1) / (eigen ** 2).sum(-1))
    strongest = weights.argmax(-1)
    inside = weights.max(-1) > 0.5
    direction = np.take_along_axis(np.stack([t for _, t in parts], -2), strongest[..., None, None], -2)[..., 0, :]
    direction = np.where(inside[..., None], direction, 0.0)
    bundle = np.where(inside, strongest + 1, 0)

    image = vtkImageData()
    image.SetDimensions(*DIMENSIONS)
    image.SetOrigin(*origin)
    image.SetSpacing(SPACING, SPACING, SPACING)

    def add(name, values, components):
        array = numpy_to_vtk(np.ascontiguousarray(values.reshape(-1, components)), deep=1)
        array.SetName(name)
        image.GetPointData().AddArray(array)

    add("Tensors", np.stack([d[..., 0, 0], d[..., 1, 1], d[..., 2, 2], d[..., 0, 1], d[..., 1, 2], d[..., 0, 2]], -1), 6)
    add("FractionalAnisotropy", fa, 1)
    add("FibreDirection", direction, 3)
    add("Bundle", bundle.astype(np.int32), 1)
    image.GetPointData().SetActiveScalars("FractionalAnisotropy")
    return image


def main():
    output = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                                 "fibre-phantom.vti")
    writer = vtkXMLImageDataWriter()
    writer.SetFileName(output)
    writer.SetInputData(phantom())
    writer.SetDataModeToAppended()
    writer.SetCompressorTypeToZLib()
    if not writer.Write():
        sys.exit("make_fibre_phantom: could not write " + output)
    print("wrote", output)


if __name__ == "__main__":
    main()
