#!/usr/bin/env python3
"""Erosion map figures from a `monosph study` folder's study.csv: removed mass per impact at each
angle and speed (also per grain mass), the angle of the maximum per speed, the speed exponent
(least-squares slope of log m against log v over the speeds with removal) per angle and of the
sum over the angles. Usage: analyse.py study.csv [grain_mass_per_metre]"""
import csv, math, sys

rows = list(csv.DictReader(open(sys.argv[1])))
grain = float(sys.argv[2]) if len(sys.argv) > 2 else 7870 * math.pi * 5e-5**2
m = {}
for r in rows:
    if r["status"] != "completed":
        continue
    m[(float(r["variables.angle"]), float(r["variables.speed"]))] = float(r["removed_mass_value"])
angles = sorted({a for a, _ in m})
speeds = sorted({v for _, v in m})

def slope(pts):
    pts = [(math.log(v), math.log(y)) for v, y in pts if y > 0]
    if len(pts) < 2:
        return float("nan")
    n = len(pts); sx = sum(p[0] for p in pts); sy = sum(p[1] for p in pts)
    sxx = sum(p[0] ** 2 for p in pts); sxy = sum(p[0] * p[1] for p in pts)
    return (n * sxy - sx * sy) / (n * sxx - sx * sx)

print("removed mass per impact [kg/m] (per grain mass)")
print("angle | " + " | ".join("%g m/s" % v for v in speeds) + " | exponent")
for a in angles:
    cells = ["%.3g (%.3g)" % (m[(a, v)], m[(a, v)] / grain) if (a, v) in m else "-" for v in speeds]
    print("%g | %s | %.2f" % (a, " | ".join(cells), slope([(v, m.get((a, v), 0)) for v in speeds])))
for v in speeds:
    vals = [(m.get((a, v), 0), a) for a in angles]
    best = max(vals)
    normal = m.get((90.0, v), float("nan"))
    print("speed %g: maximum %.3g kg/m at %g deg; normal/maximum %.2f" %
          (v, best[0], best[1], normal / best[0] if best[0] > 0 else float("nan")))
tot = [(v, sum(m.get((a, v), 0) for a in angles)) for v in speeds]
print("exponent of the sum over the angles: %.2f (speeds with removal: %s)" %
      (slope(tot), ", ".join("%g" % v for v, y in tot if y > 0)))
