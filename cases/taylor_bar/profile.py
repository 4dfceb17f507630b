#!/usr/bin/python3
"""Outer diameter of a Taylor bar against height: python3 profile.py OUT_DIR [OUT_DIR ...].

Reads the last frame of each run (3D) and prints, for heights h above the anvil face, the outer
diameter of the particles whose centres lie within dp/2 of h: 2 (max radius + dp/2). Height 0 is
the footprint (the `diameter_x` probe measures the same along x only). Needs Debian's
python3-vtk9 and python3-numpy."""
import json, sys

import numpy as np

from frames import frames, read

heights = [0.0, 0.25, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0]  # mm above the anvil face
print("dp [mm] | " + " | ".join(f"{h:g} mm" for h in heights))
for out in sys.argv[1:]:
    dp = json.load(open(out + "/summary.json"))["dp"]
    (x,) = read(frames(out)[-1][1])
    rad = np.hypot(x[:, 0], x[:, 1])
    z = x[:, 2] - x[:, 2].min() + 0.5 * dp  # height of the centres above the anvil face
    row = []
    for h in heights:
        sel = np.abs(z - max(h * 1e-3, 0.5 * dp)) < 0.5 * dp
        row.append(f"{2e3 * (rad[sel].max() + 0.5 * dp):.2f}" if sel.any() else "-")
    print(f"{dp * 1e3:.3f} | " + " | ".join(row))
