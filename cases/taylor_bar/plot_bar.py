#!/usr/bin/python3
"""Taylor bar frames: python3 plot_bar.py OUT_DIR PNG [TITLE].

Plastic strain in the slice |y| < dp at 20, 40 and 100 us and the impact face (z < 3 dp above
the lowest particle) seen from below at the last frame, from a 3D run of scene.yaml.
Needs Debian's python3-vtk9, python3-numpy and python3-matplotlib."""
import json, sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from frames import frames as run_frames, read

out, png = sys.argv[1], sys.argv[2]
title = sys.argv[3] if len(sys.argv) > 3 else out
dp = json.load(open(out + "/summary.json"))["dp"]
frames = run_frames(out)


def load(path):
    return read(path, "plastic_strain")


def nearest(t):
    return min(frames, key=lambda f: abs(f[0] - t))


fig, axes = plt.subplots(1, 4, figsize=(16, 5.5), gridspec_kw={"width_ratios": [1, 1, 1, 1.6]})
for ax, t in zip(axes[:3], [20e-6, 40e-6, 100e-6]):
    tf, name = nearest(t)
    x, ep = load(name)
    s = np.abs(x[:, 1]) < dp
    sc = ax.scatter(1e3 * x[s, 0], 1e3 * x[s, 2], c=ep[s], s=2, cmap="jet", vmin=0, vmax=2)
    ax.set_title(f"t = {tf * 1e6:.0f} us, |y| < dp")
    ax.set_xlim(-8, 8), ax.set_ylim(0, 38), ax.set_aspect("equal")
    ax.set_xlabel("x (mm)"), ax.set_ylabel("z (mm)")
tf, name = frames[-1]
x, ep = load(name)
s = x[:, 2] < x[:, 2].min() + 3 * dp
order = np.argsort(-x[s, 2])  # lowest particles drawn last (on top, seen from below)
ax = axes[3]
ax.scatter(1e3 * x[s, 0][order], 1e3 * x[s, 1][order], c=ep[s][order], s=4, cmap="jet", vmin=0, vmax=2)
ax.set_title(f"impact face (z < 3 dp) from below, {tf * 1e6:.0f} us", fontsize=10)
ax.set_aspect("equal"), ax.set_xlabel("x (mm)"), ax.set_ylabel("y (mm)")
fig.colorbar(sc, ax=axes, label="plastic strain", shrink=0.8)
fig.suptitle(title)
fig.savefig(png, dpi=70)
print(f"wrote {png} ({len(x)} particles, last frame {tf * 1e6:.1f} us)")
