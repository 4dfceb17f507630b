#!/usr/bin/python3
"""Figures of the abrasive-flow-machining case (MMB 2020 Fig. 16 style).

usage: plot.py OUT.png RUN_WITH_CONTROL RUN_WITHOUT_CONTROL
Each RUN is an output folder of `monosph run` (VTU frames, probes.csv). Top: the last frame with
hourglass control, bottom: without (solid grey, grains light blue, fluid dark blue; solid
particles coloured by the disorder measure). Middle: disorder, removed mass and grain impacts against time. Right: the roughness outline
(height against x) at the start and the end.
Needs python3-vtk9 and python3-matplotlib (Debian)."""
import csv
import json
import glob
import os
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError as e:
    sys.exit(f"plot.py: {e} (apt-get install python3-vtk9 python3-matplotlib)")


def frame(run, which=-1):
    files = sorted(glob.glob(os.path.join(run, "*_[0-9]*.vtu")))
    if not files:
        sys.exit(f"plot.py: no VTU frames in {run}")
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(files[which])
    r.Update()
    g = r.GetOutput()
    d = {"x": vtk_to_numpy(g.GetPoints().GetData())}
    pd = g.GetPointData()
    for i in range(pd.GetNumberOfArrays()):
        d[pd.GetArrayName(i)] = vtk_to_numpy(pd.GetArray(i))
    t = g.GetFieldData().GetArray("TimeValue")
    d["time"] = t.GetValue(0) if t else float("nan")
    return d


def outline(d, dp=0.5):
    """Top of the PMMA (highest solid particle + dp/2) in columns of width dp, x in um."""
    x = d["x"][d["phase"] == 1] * 1e6
    cols = np.floor(x[:, 0] / dp).astype(int)
    xs = np.unique(cols)
    return (xs + 0.5) * dp, np.array([x[cols == c, 1].max() + dp / 2 for c in xs])


def probes(run):
    with open(os.path.join(run, "probes.csv")) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    out, runs = sys.argv[1], sys.argv[2:]
    labels = ["with hourglass control", "without hourglass control"]
    fig = plt.figure(figsize=(19, 7.5))
    gs = fig.add_gridspec(2, 3, width_ratios=[2.2, 1, 1])
    frames = [frame(run) for run in runs]
    # One grey scale for both maps, up to the largest disorder of their solids.
    vmax = max(max(d.get("disorder", np.zeros(1))[d["phase"] == 1].max(), 1e-6) for d in frames)
    for k, d in enumerate(frames):
        ax = fig.add_subplot(gs[k, 0])
        x, ph = d["x"] * 1e6, d["phase"]
        dis = d.get("disorder", np.zeros(len(x)))
        s = 2.0
        ax.scatter(x[ph == 0, 0], x[ph == 0, 1], s=s, c="#1f3b73", lw=0)
        ax.scatter(x[ph == 3, 0], x[ph == 3, 1], s=s, c="#555555", lw=0)
        sc = ax.scatter(x[ph == 1, 0], x[ph == 1, 1], s=s, c=dis[ph == 1], cmap="Greys",
                        vmin=-vmax / 2, vmax=vmax, lw=0)
        ax.scatter(x[ph == 2, 0], x[ph == 2, 1], s=s, c="#8ecae6", lw=0)
        ax.set_aspect("equal")
        ax.set_xlim(0, 60)
        ax.set_ylim(-10, 31.5)
        ax.set_title(f"{labels[k]}, t = {d['time'] * 1e6:.2f} us (solid grey = disorder, dp)")
        ax.set_xlabel("x [um]")
        ax.set_ylabel("y [um]")
        fig.colorbar(sc, ax=ax, fraction=0.02)
    ax1 = fig.add_subplot(gs[0, 1])
    ax2 = fig.add_subplot(gs[1, 1])
    ax3 = ax2.twinx()
    for k, run in enumerate(runs):
        p = probes(run)
        ax1.semilogy(p["time"] * 1e6, np.maximum(p["disorder"], 1e-8), label=labels[k])
        ax2.plot(p["time"] * 1e6, p["removed_mass"] * 1e6, label=f"removed mass, {labels[k]}")
        ax3.plot(p["time"] * 1e6, p["grain_impacts"], "--", label=f"impacts, {labels[k]}")
    ax1.set_ylabel("largest disorder of the PMMA [dp]")
    ax2.set_ylabel("removed PMMA mass [mg per m depth]")
    ax3.set_ylabel("grain impacts (dashed)")
    ax3.legend(loc="lower right")
    # The roughness outline (height against x) at the start and the end of each run.
    for k, run in enumerate(runs):
        ax = fig.add_subplot(gs[k, 2])
        with open(os.path.join(run, "summary.json")) as f:
            dp = json.load(f)["dp"] * 1e6
        for d, style, when in ((frame(run, 0), "k:", "start"), (frames[k], "r-", "end")):
            xo, yo = outline(d, dp)
            ax.step(xo, yo, style, where="mid", label=f"{when}, t = {d['time'] * 1e6:.2f} us")
        ax.set_xlim(20, 40)
        ax.set_ylim(-1, 6.5)
        ax.set_xlabel("x [um]")
        ax.set_ylabel("top of the PMMA [um]")
        ax.set_title(f"roughness outline, {labels[k]}")
        ax.grid(True)
        ax.legend(loc="lower center")
    for a in (ax1, ax2):
        a.set_xlabel("t [us]")
        a.grid(True)
        a.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"written {out}")


if __name__ == "__main__":
    main()
