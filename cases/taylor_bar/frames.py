"""Frames of a monosph output folder, shared by the Taylor-bar scripts.

Needs Debian's python3-vtk9 and python3-numpy."""
import glob
import re

import vtk
from vtk.util.numpy_support import vtk_to_numpy


def frames(out):
    """(time, path) of every frame listed in the run's .pvd, in time order."""
    pvd = open(glob.glob(out + "/*.pvd")[0]).read()
    found = re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', pvd)
    return [(float(t), out + "/" + f) for t, f in found]


def read(path, *fields):
    """Positions of the particles in one .vtu file, then each named point array."""
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    g = r.GetOutput()
    x = vtk_to_numpy(g.GetPoints().GetData())
    return (x,) + tuple(vtk_to_numpy(g.GetPointData().GetArray(f)) for f in fields)
