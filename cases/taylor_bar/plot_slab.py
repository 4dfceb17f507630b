#!/usr/bin/python3
"""2D Taylor slab at rest: python3 plot_slab.py PNG RUN [RUN ...], RUN = LABEL=OUT_DIR.

Plastic strain of the last frame of each run of scene_2d.yaml, side by side.
Needs Debian's python3-vtk9, python3-numpy and python3-matplotlib."""
import glob, sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import vtk
from vtk.util.numpy_support import vtk_to_numpy

png, runs = sys.argv[1], [a.split("=", 1) for a in sys.argv[2:]]
fig, axes = plt.subplots(1, len(runs), figsize=(6.5 * len(runs), 5.5), squeeze=False)
for ax, (label, out) in zip(axes[0], runs):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(sorted(glob.glob(out + "/*_[0-9]*.vtu"))[-1])
    r.Update()
    g = r.GetOutput()
    x = vtk_to_numpy(g.GetPoints().GetData()) * 1e3
    ep = vtk_to_numpy(g.GetPointData().GetArray("plastic_strain"))
    t = g.GetFieldData().GetArray("TimeValue").GetValue(0)
    sc = ax.scatter(x[:, 0], x[:, 1], c=ep, s=6, cmap="jet", vmin=0, vmax=2)
    ax.set_aspect("equal")
    ax.set_xlim(-14, 14)
    ax.set_title(f"{label}, {t * 1e6:.0f} us")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    fig.colorbar(sc, ax=ax, label="equivalent plastic strain")
fig.tight_layout()
fig.savefig(png, dpi=90)
print("written", png)
