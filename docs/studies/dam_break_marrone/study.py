"""Dam break in the Marrone et al. (2011) geometry at H/40, H/80, H/160 against the converged
references: the surge front (H/400 WCSPH, t* <= 2.3) and the pressure at sensor P1 on the right
wall (De Courcy et al. 2024). Writes results.csv, front_<n>.csv / p1_<n>.csv (the probe series,
thinned) and dam_break_marrone.png here.

    /usr/bin/python3 study.py            # run what is missing, then collect
    /usr/bin/python3 study.py --collect  # only collect runs already in OUT
Runs go to $OUT (default /tmp/dam_break_marrone_study/H<n>), one thread each, one at a time.
"""
import argparse
import csv
import json
import os

import numpy as np

import runs

RESOLUTIONS = [40, 80, 160]
OUT = os.environ.get("OUT", "/tmp/dam_break_marrone_study")


def run_dir(n):
    return os.path.join(OUT, "H%d" % n)


def collect(n):
    d = run_dir(n)
    with open(os.path.join(d, "summary.json")) as f:
        s = json.load(f)
    p = np.genfromtxt(os.path.join(d, "probes.csv"), delimiter=",", names=True)
    t = p["time"] * runs.TS
    ps = p["P1"] / (runs.RHO0 * runs.G * runs.H)
    fe = runs.front_errors(p, runs.H / n)
    pm = runs.pressure_metrics(t, ps)
    # the series, thinned: the front every 0.01 in t* up to 2.6, P1 at every probe sample
    keep = np.nonzero(t <= 2.6)[0][::5]
    np.savetxt(os.path.join(runs.HERE, "front_%d.csv" % n),
               np.column_stack([t[keep], p["front"][keep] / runs.H]), delimiter=",", fmt="%.5f",
               header="t_sqrt_g_over_H,x_front_over_H (largest fluid particle centre x, H/%d)" % n,
               comments="")
    keep = np.nonzero(t >= 2.0)[0]
    np.savetxt(os.path.join(runs.HERE, "p1_%d.csv" % n), np.column_stack([t[keep], ps[keep]]),
               delimiter=",", fmt="%.5f",
               header="t_sqrt_g_over_H,p1_over_rho_g_H (sensor P1, H/%d)" % n, comments="")
    row = {"resolution": "H/%d" % n, "dp_m": runs.H / n, "particles": s["particles"],
           "steps": s["steps"], "wall_s": round(s["wall_seconds"], 1), "status": s["status"],
           "t_star_end": round(s["simulated_time"] * runs.TS, 3),
           "front_max_err": round(fe["centre"]["max"], 5),
           "front_max_err_t_star": fe["centre"]["t_max"],
           "front_rms_err": round(fe["centre"]["rms"], 5),
           "front_err_2p3": round(fe["centre"]["last"], 5),
           "front_surface_max_err": round(fe["surface"]["max"], 5),
           "front_surface_rms_err": round(fe["surface"]["rms"], 5),
           "impact_t_star": None if pm["impact"] is None else round(pm["impact"], 4),
           "peak_p": None if pm["peak"] is None else round(pm["peak"], 3),
           "peak_t_star": None if pm["t_peak"] is None else round(pm["t_peak"], 4),
           "min_distance_dp": round(float(p["min_distance"].min()), 3),
           "max_wall_penetration_dp": round(float(p["wall_penetration"].max()) / (runs.H / n), 3)}
    for (lo, hi), v in zip(runs.P_WINDOWS, pm["windows"]):
        row["p_mean_%g_%g" % (lo, hi)] = None if v is None else round(v, 3)
    return row, (t, p["front"] / runs.H, ps)


def reference_row():
    t, p = runs.reference_pressure()
    pm = runs.pressure_metrics(t, p)
    row = {"resolution": "reference", "impact_t_star": round(pm["impact"], 4),
           "peak_p": round(pm["peak"], 3), "peak_t_star": round(pm["t_peak"], 4)}
    for (lo, hi), v in zip(runs.P_WINDOWS, pm["windows"]):
        row["p_mean_%g_%g" % (lo, hi)] = round(v, 3)
    return row


def running_mean(t, y, width):
    """Mean of y over [t - width/2, t + width/2] where the window is covered (uniform samples)."""
    k = max(1, int(round(width / np.median(np.diff(t)))))
    mean = np.convolve(y, np.ones(k) / k, mode="valid")
    return t[k // 2: k // 2 + len(mean)], mean


def figure(series):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    ref = runs.read_csv(runs.FRONT_REF)
    tr, pr = runs.reference_pressure()
    fig, ax = plt.subplots(1, 3, figsize=(17, 4.8), gridspec_kw={"width_ratios": [1, 0.8, 1.3]})
    ax[0].plot(ref["t_sqrt_g_over_H"], ref["x_front_over_H"], "k-", lw=2.5,
               label="WCSPH H/400 (reference)")
    m = ref["t_sqrt_g_over_H"] <= runs.FRONT_WINDOW + 1e-9
    for n, (t, x, p) in series.items():
        c = ax[0].plot(t, x, lw=1.2, label="monosph H/%d" % n)[0].get_color()
        e = np.interp(ref["t_sqrt_g_over_H"][m], t, x) / ref["x_front_over_H"][m] - 1
        ax[1].plot(ref["t_sqrt_g_over_H"][m], 100 * e, color=c, label="H/%d" % n)
    ax[0].axvline(runs.FRONT_WINDOW, color="grey", ls=":", lw=1)
    ax[0].set(xlim=(0, 2.6), ylim=(1.9, 5.5), xlabel="t (g/H)$^{1/2}$", ylabel="x$_f$ / H",
              title="surge front (largest particle centre x)")
    ax[0].legend()
    ax[1].axhline(0, color="k", lw=1)
    ax[1].set(xlim=(0, 2.3), xlabel="t (g/H)$^{1/2}$", ylabel="x$_f$ / x$_{f,ref}$ - 1 (%)",
              title="front error against H/400")
    ax[1].legend()
    ax[2].plot(tr, pr, "k-", lw=2.5, label="De Courcy et al. 2024 (H/400)")
    for n, (t, x, p) in series.items():
        k = t >= 2.0
        c = ax[2].plot(t[k], p[k], lw=0.5, alpha=0.45)[0].get_color()
        ax[2].plot(*running_mean(t[k], p[k], 0.1), color=c, lw=1.6,
                   label="monosph H/%d (thin: every sample; thick: mean over 0.1)" % n)
    ax[2].set(xlim=(2, 7), ylim=(-0.5, 5), xlabel="t (g/H)$^{1/2}$", ylabel="p / ($\\rho$ g H)",
              title="sensor P1, right wall, y = 1.8-10.2 mm")
    ax[2].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(runs.HERE, "dam_break_marrone.png"), dpi=100)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--collect", action="store_true")
    ap.add_argument("--only", type=int, nargs="*", default=RESOLUTIONS)
    a = ap.parse_args()
    rows, series = [], {}
    for n in a.only:
        if not a.collect and not os.path.exists(os.path.join(run_dir(n), "summary.json")):
            runs.run(n, run_dir(n))
        if os.path.exists(os.path.join(run_dir(n), "summary.json")):
            row, s = collect(n)
            rows.append(row)
            series[n] = s
    rows.append(reference_row())
    keys = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    with open(os.path.join(runs.HERE, "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        for r in rows:
            w.writerow(r)
    figure(series)
    for r in rows:
        print(r)


if __name__ == "__main__":
    main()
