"""Runs of cases/dam_break/scene_marrone.yaml at H/n and their comparison with the references.

Imported by study.py (the study) and usable alone:
    /usr/bin/python3 runs.py 40 [--layers 3] [--set key=value ...] [--out DIR]
"""
import argparse
import io
import json
import math
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
SCENE = os.path.join(ROOT, "cases", "dam_break", "scene_marrone.yaml")
FRONT_REF = os.path.join(ROOT, "cases", "dam_break", "reference_front_wcsph_H400.csv")
P1_REF = os.path.join(ROOT, "cases", "dam_break", "reference_P1_decourcy2024.csv")
BIN = os.environ.get("MONOSPH", os.path.join(ROOT, "build", "release", "monosph"))

H, W, G, RHO0 = 0.6, 1.2, 9.81, 1000.0
TS = math.sqrt(G / H)          # t* = t sqrt(g / H)
TANK_TOP = 4.0                 # open tank 4 m tall (as TrixiParticles.jl's setup): the jet runs up past 4H
SENSOR_Y, SENSOR_SIZE = 0.006, 0.0084   # De Courcy et al. 2024 P1: y from 1.8 to 10.2 mm
FRONT_WINDOW = 2.3             # compare the front for t* <= 2.3 (before the far wall)
# Windows of t* over which the mean P1 is compared (first peak, decay, plateau, second rise).
P_WINDOWS = [(2.4, 2.6), (2.6, 2.8), (2.8, 3.0), (3.0, 4.0), (4.0, 5.0), (5.0, 6.0), (6.0, 7.0)]


def geometry_sets(n, layers):
    """--set values for H/n with `layers` wall layers: the tank length is the nearest whole number
    of dp to 5.366 H (the lattice needs whole numbers), the sensor sits on that face."""
    dp = H / n
    length = round(5.366 * H / dp) * dp
    t = layers * dp
    return [
        "dp=%r" % dp,
        "domain.min=[%r,%r]" % (-t, -t),
        "domain.max=[%r,%r]" % (length + t, TANK_TOP),
        "bodies.1.shape.difference.0.box.min=[%r,%r]" % (-t, -t),
        "bodies.1.shape.difference.0.box.max=[%r,%r]" % (length + t, TANK_TOP),
        "bodies.1.shape.difference.1.box.max=[%r,%r]" % (length, TANK_TOP),
        "probes.list.1.center=[%r,%r]" % (length, SENSOR_Y),
    ], length


def run(n, out, layers=3, extra=(), end=7.0 / TS, every=None):
    """Runs H/n into `out` to t* = 7 unless `end` (one thread, frames only at the start and the
    end); returns the summary."""
    sets, _ = geometry_sets(n, layers)
    sets += ["output.every=0"] + list(extra)
    if end is not None:
        sets.append("end_time=%r" % end)
    if every is not None:
        sets.append("probes.every=%r" % every)
    cmd = [BIN, "run", SCENE, "--threads", "1", "--quiet", "--out", out, "--set"] + sets
    subprocess.run(cmd, check=False)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def read_csv(path):
    lines = [l for l in open(path) if not l.startswith("#")]
    return np.genfromtxt(io.StringIO("".join(lines)), delimiter=",", names=True)


def front_errors(probes, dp):
    """Relative error of the front (largest fluid particle centre x, as the reference defines it)
    at the reference's samples with t* <= 2.3: (max |e| with its sign, its t*, RMS, e at 2.3),
    and the same for the front surface x + dp/2 against the reference's + dp_ref/2."""
    ref = read_csv(FRONT_REF)
    t = probes["time"] * TS
    m = (ref["t_sqrt_g_over_H"] <= FRONT_WINDOW + 1e-9) & (ref["t_sqrt_g_over_H"] <= t.max())
    tr, xr = ref["t_sqrt_g_over_H"][m], ref["x_front_m"][m]
    xs = np.interp(tr, t, probes["front"])
    out = {}
    for tag, a, b in (("centre", xs, xr), ("surface", xs + dp / 2, xr + 0.0015 / 2)):
        e = (a - b) / b
        k = int(np.argmax(np.abs(e)))
        out[tag] = {"max": float(e[k]), "t_max": float(tr[k]), "rms": float(np.sqrt(np.mean(e**2))),
                    "last": float(e[-1]), "t_last": float(tr[-1])}
    return out


def impact(t_star, p_star, threshold=0.5):
    """First t* at which p/(rho g H) reaches `threshold` (linear interpolation), None if never."""
    k = np.nonzero(p_star >= threshold)[0]
    if len(k) == 0:
        return None
    k = k[0]
    if k == 0:
        return float(t_star[0])
    a, b = p_star[k - 1], p_star[k]
    return float(t_star[k - 1] + (t_star[k] - t_star[k - 1]) * (threshold - a) / (b - a))


def window_means(t_star, p_star):
    """Time-weighted mean of p* over each window of P_WINDOWS (None when not covered)."""
    out = []
    for lo, hi in P_WINDOWS:
        if t_star.max() < hi:
            out.append(None)
            continue
        tt = np.linspace(lo, hi, 2001)
        out.append(float(np.mean(np.interp(tt, t_star, p_star))))
    return out


def pressure_metrics(t_star, p_star):
    k = np.nonzero((t_star >= 2.2) & (t_star <= 2.8))[0]
    peak = (float(p_star[k].max()), float(t_star[k][np.argmax(p_star[k])])) if len(k) else (None, None)
    return {"impact": impact(t_star, p_star), "peak": peak[0], "t_peak": peak[1],
            "windows": window_means(t_star, p_star)}


def reference_pressure():
    """De Courcy et al. (2024) P1 in time order (the digitised rows are not all in order)."""
    ref = read_csv(P1_REF)
    k = np.argsort(ref["t_sqrt_g_over_H"], kind="stable")
    return ref["t_sqrt_g_over_H"][k], ref["p_over_rho_g_H"][k]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("n", type=int)
    ap.add_argument("--layers", type=int, default=3)
    ap.add_argument("--set", nargs="*", default=[])
    ap.add_argument("--end", type=float, default=7.0 / TS, help="end time in s (default t* = 7)")
    ap.add_argument("--out")
    a = ap.parse_args()
    out = a.out or "/tmp/dam_break_marrone_H%d" % a.n
    s = run(a.n, out, a.layers, a.set, a.end)
    p = np.genfromtxt(os.path.join(out, "probes.csv"), delimiter=",", names=True)
    print(s["status"], "t* = %.3f" % (s["simulated_time"] * TS), "steps", s["steps"],
          "wall %.1f s" % s["wall_seconds"], "particles", s["particles"])
    print(json.dumps(front_errors(p, H / a.n)))
    print(json.dumps(pressure_metrics(p["time"] * TS, p["P1"] / (RHO0 * G * H))))
    print("min distance %.3f dp" % p["min_distance"].min())


if __name__ == "__main__":
    sys.exit(main())
