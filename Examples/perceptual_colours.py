"""The examples' colour map: viridis (perceptual, colour-blind safe), the same
as riemann-studio's default map, as a VTK colour transfer function."""

from vtkmodules.vtkRenderingCore import vtkColorTransferFunction

# viridis at six positions in [0, 1] (matplotlib's values).
VIRIDIS = ((0.0, 0.267, 0.005, 0.329), (0.25, 0.254, 0.265, 0.530), (0.5, 0.164, 0.471, 0.558),
           (0.75, 0.135, 0.659, 0.518), (0.875, 0.478, 0.821, 0.318), (1.0, 0.993, 0.906, 0.144))


def viridis(low, high):
    """viridis from `low` to `high`."""
    lut = vtkColorTransferFunction()
    for x, r, g, b in VIRIDIS:
        lut.AddRGBPoint(low + x * (high - low), r, g, b)
    return lut
