#!/usr/bin/env python3
"""Erosion map at two resolutions side by side, from two `monosph study` folders (study.csv and each
run's probes.csv): removed mass per impact [kg/m] and in target particles (particle mass
rho dp^2 per metre, rho = 2800 kg/m^3 for the Al6061-T6 preset), the angle of the maximum and
normal/maximum per speed, the least-squares speed exponent (slope of log m against log v over the
speeds with removal > 0) per angle and of the sum over the angles, and the time of the last
change of the removed_mass probe. Usage: compare.py COARSE_DIR DP_COARSE FINE_DIR DP_FINE"""
import csv, glob, math, os, sys

RHO = 2800.0


def load(folder, dp):
    rows = list(csv.DictReader(open(os.path.join(folder, "study.csv"))))
    m, wall, last = {}, {}, {}
    for r in rows:
        if r["status"] != "completed":
            continue
        a, v = float(r["variables.angle"]), float(r["variables.speed"])
        m[(a, v)] = float(r["removed_mass_value"])
        wall[(a, v)] = float(r["wall_seconds"])
        run = glob.glob(os.path.join(folder, "run*_variables.angle-%g_variables.speed-%g" % (a, v)))
        if run:
            p = list(csv.DictReader(open(os.path.join(run[0], "probes.csv"))))
            final = float(p[-1]["removed_mass"])
            t, prev = 0.0, 0.0
            for row in p:  # time of the first sample with the final value after the last change
                y = float(row["removed_mass"])
                if y != prev:
                    t = float(row["time"])
                prev = y
            last[(a, v)] = t
    last = {k: t for k, t in last.items() if m[k] > 0}
    return m, wall, last, RHO * dp * dp


def slope(pts):
    pts = [(math.log(v), math.log(y)) for v, y in pts if y > 0]
    if len(pts) < 2:
        return float("nan")
    n = len(pts); sx = sum(p[0] for p in pts); sy = sum(p[1] for p in pts)
    sxx = sum(p[0] ** 2 for p in pts); sxy = sum(p[0] * p[1] for p in pts)
    return (n * sxy - sx * sy) / (n * sxx - sx * sx)


maps = [(sys.argv[1], float(sys.argv[2])), (sys.argv[3], float(sys.argv[4]))]
data = [load(f, dp) for f, dp in maps]
angles = sorted({a for d in data for a, _ in d[0]})
speeds = sorted({v for d in data for _, v in d[0]})
names = ["dp=%g" % dp for _, dp in maps]

print("removed mass per impact [kg/m] (target particles): %s | %s" % tuple(names))
print("angle | " + " | ".join("%g m/s" % v for v in speeds) + " | exponent")
for a in angles:
    cells = []
    for v in speeds:
        c = []
        for m, _, _, pm in data:
            c.append("%.3g (%d)" % (m[(a, v)], round(m[(a, v)] / pm)) if (a, v) in m else "-")
        cells.append(" / ".join(c))
    ex = " / ".join("%.2f" % slope([(v, m.get((a, v), 0)) for v in speeds]) for m, *_ in data)
    print("%g | %s | %s" % (a, " | ".join(cells), ex))
for v in speeds:
    parts = []
    for (m, *_), nm in zip(data, names):
        vals = [(m[(a, v)], a) for a in angles if (a, v) in m]
        if not vals:
            parts.append("%s: -" % nm)
            continue
        best = max(vals)
        tied = [a for y, a in vals if y == best[0]]
        normal = m.get((90.0, v), float("nan"))
        parts.append("%s: maximum %.3g kg/m at %s deg, normal/maximum %.2f" % (
            nm, best[0], "/".join("%g" % a for a in tied),
            normal / best[0] if best[0] > 0 else float("nan")))
    print("speed %g: %s" % (v, "; ".join(parts)))
for (m, *_), nm in zip(data, names):
    common = [a for a in angles if all((a, v) in m for v in speeds)]
    tot = [(v, sum(m[(a, v)] for a in common)) for v in speeds]
    print("%s: exponent of the sum over %s deg: %.2f (speeds with removal: %s); 150->300 of the "
          "15+30+90 sum: %s" % (
              nm, ",".join("%g" % a for a in common), slope(tot),
              ", ".join("%g" % v for v, y in tot if y > 0),
              "%.2f" % (math.log(sum(m[(a, 300.0)] for a in (15.0, 30.0, 90.0)) /
                                 sum(m[(a, 150.0)] for a in (15.0, 30.0, 90.0))) / math.log(2))
              if all((a, s) in m for a in (15.0, 30.0, 90.0) for s in (150.0, 300.0)) else "-"))
for (m, wall, last, _), nm in zip(data, names):
    print("%s: wall time per run %.0f-%.0f s (total %.0f s); last change of removed_mass %.2f-%.2f us"
          % (nm, min(wall.values()), max(wall.values()), sum(wall.values()),
             min(last.values()) * 1e6, max(last.values()) * 1e6))
