#!/usr/bin/python3
"""2D Taylor slab at rest: python3 plot_slab.py PNG RUN [RUN ...], RUN = LABEL=OUT_DIR.

Plastic strain of the last frame of each run of scene_2d.yaml, side by side.
Needs Debian's python3-vtk9, python3-numpy and python3-matplotlib."""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

from frames import frames, read

png, runs = sys.argv[1], [a.split("=", 1) for a in sys.argv[2:]]
fig, axes = plt.subplots(1, len(runs), figsize=(6.5 * len(runs), 5.5), squeeze=False)
for ax, (label, out) in zip(axes[0], runs):
    t, path = frames(out)[-1]
    x, ep = read(path, "plastic_strain")
    x = x * 1e3
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
