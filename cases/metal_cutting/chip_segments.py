#!/usr/bin/python3
"""Chip segments of a metal_cutting run: python3 chip_segments.py OUT_DIR [PNG [OUT_DIR2]].

Lists when the `pieces` probe (1 + the chip segments broken off) changes and gives the segment
pitch from the cutting force:
the mean time between the deep force drops (below half the mean force) times the tool speed.
Needs Debian's python3-vtk9, python3-numpy and python3-matplotlib (for the PNG)."""
import csv, glob, re, sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

out = sys.argv[1]
speed = 10.0  # tool speed (m/s) of scene.yaml
frames = re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', open(glob.glob(out + "/*.pvd")[0]).read())


def load(run, name):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(run + "/" + name)
    r.Update()
    g = r.GetOutput()
    return vtk_to_numpy(g.GetPoints().GetData())[:, :2], g


rows = list(csv.DictReader(open(out + "/probes.csv")))
t = np.array([float(r["time"]) for r in rows])
f = -np.array([float(r["cutting_force_x"]) for r in rows])
f = f if f[len(f) // 2] > 0 else -f
steady = t > 15e-6
mean = f[steady].mean()
# deep drops: f below mean/2 after a stretch above the mean, at least 10 us after the last one
drops, armed = [], False
for k in np.where(steady)[0]:
    if f[k] > mean:
        armed = True
    elif armed and f[k] < 0.5 * mean and (not drops or t[k] - drops[-1] > 10e-6):
        drops.append(t[k])
        armed = False
print("frames: %d, last t = %.1f us" % (len(frames), float(frames[-1][0]) * 1e6))
print("mean cutting force (t > 15 us): %.1f kN/m, std %.1f" % (mean / 1e3, f[steady].std() / 1e3))
print("deep force drops at t = %s us" % ", ".join("%.1f" % (d * 1e6) for d in drops))
if len(drops) > 1:
    period = np.diff(drops).mean()
    print("segment period %.1f us -> pitch %.0f um of tool travel" % (period * 1e6, period * speed * 1e6))
changes = [(t[k], p) for k, p in enumerate(float(r["pieces"]) for r in rows) if k == 0 or p != float(rows[k - 1]["pieces"])]
print("pieces: %s" % ", ".join("%d from %.1f us" % (p, tk * 1e6) for tk, p in changes))
if len(sys.argv) > 2:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    runs = [out] + sys.argv[3:]
    want = [40e-6, 80e-6, 120e-6, 150e-6]
    fig, ax = plt.subplots(2 * len(runs), len(want) + 1, figsize=(24, 8 * len(runs)), constrained_layout=True, squeeze=False)
    for r, run in enumerate(runs):
        frames = re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', open(glob.glob(run + "/*.pvd")[0]).read())
        label = "hourglass control" if r == 0 else "no hourglass control (AV + AS)"
        for c, w in enumerate(want):
            tm, name = min(frames, key=lambda q: abs(float(q[0]) - w))
            x, g = load(run, name)
            tool = 3.02e-3 - speed * float(tm)  # tool tip x (scene.yaml)
            for k, (field, hi, cm) in enumerate([("von_mises", 6e8, "jet"), ("damage", 1, "jet")]):
                a = ax[2 * r + k, c]
                v = vtk_to_numpy(g.GetPointData().GetArray(field))
                sc = a.scatter(x[:, 0] * 1e3, x[:, 1] * 1e3, s=4, c=v, cmap=cm, vmin=0, vmax=hi)
                a.plot([tool * 1e3, tool * 1e3, tool * 1e3 + 0.58], [1.5, 0.3, 0.371], "k-", lw=2)
                a.set_aspect("equal")
                a.set_xlim(tool * 1e3 - 0.9, tool * 1e3 + 0.4)
                a.set_ylim(0.2, 1.5)
                a.set_title("%s, t = %.0f us: %s" % (label, float(tm) * 1e6, field))
                if c == len(want) - 1:
                    fig.colorbar(sc, ax=a, shrink=0.7)
        rows = list(csv.DictReader(open(run + "/probes.csv")))
        tt = np.array([float(q["time"]) for q in rows])
        ff = np.abs(np.array([float(q["cutting_force_x"]) for q in rows]))
        for k in range(2):
            a = ax[2 * r + k, len(want)]
            a.plot(tt * 1e6, ff / 1e3)
            if r == 0 and k == 0:
                for d in drops:
                    a.axvline(d * 1e6, color="r", lw=0.5)
            a.set_xlim(0, 150)
            a.set_xlabel("time (us)")
            a.set_ylabel("cutting force (kN/m)")
            a.set_title(label)
            a.grid()
    fig.savefig(sys.argv[2], dpi=45)
