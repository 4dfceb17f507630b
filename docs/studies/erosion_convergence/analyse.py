#!/usr/bin/env python3
"""Erosion convergence (issue 51) from the study_stats.csv copies in this folder (run.sh):
convergence.csv (cell, damage, dp, n, mean, 95 % interval, zeros), per cell the change from dp/2
to dp/4, the observed order and a Richardson value where three resolutions exist, and
convergence.png (removal per impact against dp with intervals; gnuplot).
Usage: analyse.py [folder]"""
import csv, glob, math, os, subprocess, sys

here = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
DP = {"dp10": 10e-6, "dp5": 5e-6, "dp2.5": 2.5e-6}
rows = []
for f in sorted(glob.glob(os.path.join(here, "dp*_stats.csv"))):
    name = os.path.basename(f)[: -len("_stats.csv")]
    dp = DP[name.split("_")[0]]
    for r in csv.DictReader(open(f)):
        if int(r["n"]) == 0:
            continue
        rows.append({
            "angle": int(float(r["variables.angle"])), "speed": int(float(r["variables.speed"])),
            "damage": "nonlocal" if float(r["variables.nonlocal"]) > 0 else "local",
            "dp": dp, "n": int(r["n"]), "mean": float(r["removed_mass_mean"]),
            "low": float(r["removed_mass_ci95_low"] or "nan"),
            "high": float(r["removed_mass_ci95_high"] or "nan"),
            "zero": int(r["removed_mass_zero"]), "failed": int(r["failed"])})
# One row per (cell, damage, dp): a later file (e.g. more seeds) replaces an earlier one.
table = {}
for r in rows:
    table[(r["angle"], r["speed"], r["damage"], r["dp"])] = r
with open(os.path.join(here, "convergence.csv"), "w") as out:
    out.write("angle,speed,damage,dp,n,mean,ci95_low,ci95_high,zero,failed\n")
    for k in sorted(table, key=lambda k: (k[0], k[1], k[2], -k[3])):
        r = table[k]
        out.write("%d,%d,%s,%g,%d,%.4g,%.4g,%.4g,%d,%d\n" % (
            r["angle"], r["speed"], r["damage"], r["dp"], r["n"], r["mean"], r["low"], r["high"],
            r["zero"], r["failed"]))

print("removed mass per impact [kg/m]: mean [95 % interval] (n) per dp")
cells = sorted({k[:3] for k in table})
for c in cells:
    ds = sorted([k[3] for k in table if k[:3] == c], reverse=True)
    ms = [table[c + (d,)]["mean"] for d in ds]
    text = "  ".join("%g um: %.3g [%.3g, %.3g] (%d)" % (
        d * 1e6, table[c + (d,)]["mean"], table[c + (d,)]["low"], table[c + (d,)]["high"],
        table[c + (d,)]["n"]) for d in ds)
    extra = ""
    if len(ms) >= 2 and ms[-2] > 0:
        extra += "; last change %+.0f %%" % (100 * (ms[-1] / ms[-2] - 1))
        lo1, hi1 = table[c + (ds[-2],)]["low"], table[c + (ds[-2],)]["high"]
        lo2, hi2 = table[c + (ds[-1],)]["low"], table[c + (ds[-1],)]["high"]
        extra += ", intervals overlap" if lo1 <= hi2 and lo2 <= hi1 else ", intervals apart"
    if len(ms) == 3 and (ms[0] - ms[1]) * (ms[1] - ms[2]) > 0:
        p = math.log(abs((ms[0] - ms[1]) / (ms[1] - ms[2]))) / math.log(2)
        if p > 0:
            inf = ms[2] + (ms[2] - ms[1]) / (2 ** p - 1)
            extra += "; observed order %.2f, extrapolated %.3g" % (p, inf)
        else:
            extra += "; the changes grow (order %.2f): no extrapolation" % p
    elif len(ms) == 3:
        extra += "; not monotone: no order"
    print("%d deg %d m/s %s: %s%s" % (c[0], c[1], c[2], text, extra))

# Shape at each dp: maximum over the two angles, normal / 30 deg, speed exponent of the sum.
for dmg in ("local", "nonlocal"):
    for d in sorted({k[3] for k in table}, reverse=True):
        get = lambda a, v: table.get((a, v, dmg, d), {}).get("mean")
        for v in (150, 300):
            if get(30, v) and get(90, v) is not None:
                print("%s %g um %d m/s: normal/30deg %.2f" % (dmg, d * 1e6, v, get(90, v) / get(30, v)))
        s150 = [get(a, 150) for a in (30, 90)]
        s300 = [get(a, 300) for a in (30, 90)]
        if None not in s150 + s300 and sum(s150) > 0:
            print("%s %g um: speed exponent of the angle sum %.2f" % (
                dmg, d * 1e6, math.log(sum(s300) / sum(s150)) / math.log(2)))

# The plot: one curve per cell and damage, mean with the interval against dp.
data = os.path.join(here, "convergence.dat")
with open(data, "w") as out:
    for c in cells:
        out.write("# %d deg %d m/s %s\n" % c)
        for d in sorted([k[3] for k in table if k[:3] == c], reverse=True):
            r = table[c + (d,)]
            lo = r["low"] if r["low"] == r["low"] else r["mean"]
            hi = r["high"] if r["high"] == r["high"] else r["mean"]
            out.write("%g %g %g %g\n" % (d * 1e6, r["mean"], lo, hi))
        out.write("\n\n")
plots = ", ".join(
    "'%s' index %d using 1:2:3:4 with yerrorlines lw 2 title '%d deg %d m/s %s'" % (data, i, *c)
    for i, c in enumerate(cells))
script = """set terminal pngcairo size 1000,650
set output '%s'
set logscale xy
set xrange [2:12] reverse
set xtics (2.5, 5, 10)
set format y '%%.0e'
set xlabel 'particle spacing dp [um] (10, 20, 40 particles across the grain)'
set ylabel 'removed mass per impact [kg/m]'
set key outside right
set title 'Erosion of Al 6061-T6 by a 100 um iron grain: mean and 95 %% interval over seeded impacts'
plot %s
""" % (os.path.join(here, "convergence.png"), plots)
try:
    subprocess.run(["gnuplot"], input=script, text=True, check=True)
    os.remove(data)
except (OSError, subprocess.CalledProcessError) as e:
    print("no plot:", e)
