#!/usr/bin/env python3
"""Collects the runs of the strip_3d studies (monosph study output folders, one per formulation
and case) into strip_3d.csv / strip_3d.md (signed period error, observed orders, wall time,
memory) and draws convergence.png (|error| against particles through the thickness) and
tip.png (tip / mid-span deflection at 4 through the thickness).
Usage: collect.py STUDY_ROOT (folders named <formulation>_<case>, e.g. tl25_cantilever).
The rows of the committed strip_3d.csv that STUDY_ROOT has no run for are kept (the run folders
are not committed), so a later session can add runs without repeating the others. A run folder
may hold time.txt (/usr/bin/time -f "%e %U %S %M": CPU seconds) and load_start.txt /
load_end.txt / load.log (/proc/loadavg at the start, the end and every 30 s): the machine's load
beside the wall time. tip.png is redrawn only when every n = 4 run is in STUDY_ROOT. A run folder whose name ends in
_half ran the half z > 0 with a mirror at mid-width (domain.mirror z_min): the same period, half
the particles; its particles, wall time and memory are marked (half).
STUDY_ROOT/checks/<formulation>_<case>_<check>/run* (check: full / half, the mirror against the
full width; slow, released at a tenth of the speed, 0.0285 m/s) go to checks.csv and the last
table of strip_3d.md."""
import csv, glob, json, math, os, sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

H = 0.02  # strip thickness
LABEL = {"eulerian": "Eulerian, xi = 0.5, Newmark 0.6", "tl": "total Lagrangian, alpha = 5",
         "tl25": "total Lagrangian, alpha = 25", "enog": "non-hourglass (Wendland)"}
root = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
from timoshenko import euler_bernoulli, stretching_ratio, timoshenko_period  # noqa: E402

# The complete reference: Timoshenko (shear, rotary inertia) and, for the strip clamped at both
# ends (immovable clamps), the hardening by mid-plane stretching at the scenes' 0.285 m/s.
BEST = {"cantilever": timoshenko_period(0.2, False, ne=400),
        "cc": timoshenko_period(0.4, True, ne=400) * stretching_ratio(0.4, 4.73004074, 0.285)[0]}
BEST_SLOW = {"cantilever": BEST["cantilever"],  # at a tenth of the speed (the checks)
             "cc": timoshenko_period(0.4, True, ne=400) * stretching_ratio(0.4, 4.73004074, 0.0285)[0]}
BEST_LABEL = {"cantilever": "Timoshenko", "cc": "Timoshenko with mid-plane stretching"}
KEYS = ["case", "formulation", "n", "width", "dp", "particles", "steps", "wall_seconds", "cpu_seconds",
        "load_start", "load_end", "load_mean", "peak_memory_mb", "period", "reference", "error"]


def load_info(run):
    """CPU seconds and 1-minute load averages of a run folder (empty strings when not recorded)."""
    info = dict(cpu_seconds="", load_start="", load_end="", load_mean="")
    try:
        e, u, sy, _ = open(os.path.join(run, "time.txt")).read().split()[-4:]
        info["cpu_seconds"] = round(float(u) + float(sy), 1)
        info["load_start"] = float(open(os.path.join(run, "load_start.txt")).read().split()[0])
        info["load_end"] = float(open(os.path.join(run, "load_end.txt")).read().split()[0])
        samples = [float(l.split()[1]) for l in open(os.path.join(run, "load.log")) if l.strip()]
        info["load_mean"] = round(sum(samples) / len(samples), 2) if samples else ""
    except (OSError, ValueError, IndexError):
        pass
    return info


rows = []
for study in sorted(glob.glob(os.path.join(root, "*_*"))):
    if not os.path.isdir(study):
        continue
    form, case = os.path.basename(study).split("_", 1)
    for run in sorted(glob.glob(os.path.join(study, "run*"))):
        try:
            j = json.load(open(os.path.join(run, "summary.json")))
        except (OSError, ValueError):
            continue
        m = j.get("metrics", {}).get("period", {})
        if j.get("status") != "completed" or "value" not in m:
            continue
        n = round(H / j["dp"])
        e = (m["value"] - m["reference"]) / m["reference"]
        rows.append(dict(formulation=form, case=case, n=n, dp=j["dp"], particles=j["particles"],
                         steps=j["steps"], wall_seconds=round(j["wall_seconds"], 1),
                         peak_memory_mb=round(j["peak_memory_bytes"] / 1e6, 1),
                         period=round(m["value"], 6), reference=m["reference"],
                         error=round(e, 5), run=run, **load_info(run),
                         width="half" if run.endswith("_half") else "full"))
have = {(r["case"], r["formulation"], r["n"]) for r in rows}
try:
    with open(os.path.join(here, "strip_3d.csv")) as f:
        for r in csv.DictReader(f):
            if (r["case"], r["formulation"], int(r["n"])) in have:
                continue
            r = {k: r.get(k) or "" for k in KEYS}
            r["width"] = r["width"] or "full"
            for k in ("n", "particles", "steps"):
                r[k] = int(r[k])
            for k in ("dp", "wall_seconds", "peak_memory_mb", "period", "reference", "error"):
                r[k] = float(r[k])
            r["run"] = None
            rows.append(r)
except OSError:
    pass
rows.sort(key=lambda r: (r["case"], r["formulation"], r["n"]))
with open(os.path.join(here, "strip_3d.csv"), "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=KEYS, extrasaction="ignore")
    w.writeheader()
    w.writerows(rows)


def update_study_folder(r):
    """The committed monosph-study table of r's folder (study.csv / study.md) with r's row: the row
    of the same dp replaced (an interrupted one), or added."""
    folder = os.path.join(here, f"{r['formulation']}_{r['case']}")
    j = json.load(open(os.path.join(r["run"], "summary.json")))
    m = j["metrics"]["period"]
    status = j["status"] + (" (half, mirror)" if r["width"] == "half" else "")
    new = dict(dp=repr(j["dp"]), particles=str(j["particles"]), steps=str(j["steps"]),
               wall_seconds=f"{j['wall_seconds']:.6g}",
               particle_steps_per_second=f"{j['particle_steps_per_second']:.6g}", status=status,
               period_value=f"{m['value']:.9g}", period_relative_error=f"{m['relative_error']:.9g}")
    with open(os.path.join(folder, "study.csv")) as f:
        rd = csv.DictReader(f)
        head, old = rd.fieldnames, [row for row in rd if float(row["dp"]) != j["dp"]]
    table = sorted(old + [new], key=lambda row: -float(row["dp"]))
    with open(os.path.join(folder, "study.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=head, lineterminator="\n")
        w.writeheader()
        w.writerows(table)
    title = open(os.path.join(folder, "study.md")).readline()
    with open(os.path.join(folder, "study.md"), "w") as f:
        f.write(title + "\n| dp | particles | wall [s] | particle-steps/s | period | error | status |\n"
                "|---|---|---|---|---|---|---|\n")
        for row in table:
            ok = row["period_value"] != ""
            f.write(f"| {row['dp']} | {row['particles']} | {float(row['wall_seconds']):.2f} | "
                    f"{float(row['particle_steps_per_second']):.3g} | "
                    f"{'%.6g' % float(row['period_value']) if ok else '–'} | "
                    f"{'%.2e' % float(row['period_relative_error']) if ok else '–'} | "
                    f"{row['status']} |\n")


for r in rows:
    if r["run"] is not None:
        update_study_folder(r)


def order(rs):
    """Least-squares slope of log|e| against log n (rs sorted by n); None with < 2 points."""
    pts = [(math.log(r["n"]), math.log(abs(r["error"]))) for r in rs if r["error"] != 0]
    if len(pts) < 2:
        return None
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    return -sum((x - mx) * (y - my) for x, y in pts) / sum((x - mx) ** 2 for x, _ in pts)


def richardson(rs):
    """Converged period T and order p of T(n) = T + C n^-p through the runs at n = 4, 6, 8 (None
    without all three or if not monotone; n = 3 is not yet in the asymptotic range)."""
    rs = [r for r in rs if r["n"] >= 4]
    if len(rs) < 3:
        return None
    (n1, t1), (n2, t2), (n3, t3) = [(r["n"], r["period"]) for r in rs[-3:]]
    if (t1 - t2) * (t2 - t3) <= 0:
        return None
    g = lambda p: (t1 - t2) / (t2 - t3) - (n1**-p - n2**-p) / (n2**-p - n3**-p)
    lo, hi = 0.05, 10.0
    if g(lo) * g(hi) > 0:
        return None
    for _ in range(200):  # bisection
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if g(lo) * g(mid) > 0 else (lo, mid)
    p = 0.5 * (lo + hi)
    return t1 - (t1 - t2) / (n1**-p - n2**-p) * n1**-p, p


def rows_ref(case):
    return euler_bernoulli(0.2, 1.87510407) if case == "cantilever" else euler_bernoulli(0.4, 4.73004074)


def mark(r, key):
    return f"{r[key]} (half)" if r["width"] == "half" else str(r[key])


with open(os.path.join(here, "strip_3d.md"), "w") as f:
    for case in ("cantilever", "cc"):
        f.write(f"\n### {'cantilever (kl = 1.8751, l/h = 10)' if case == 'cantilever' else 'clamped-clamped (kl = 4.7300, L/h = 20)'}\n\n")
        f.write("| formulation | n = 3 | n = 4 | n = 6 | n = 8 | order | wall [s] (n = 3/4/6/8) | peak memory [MB] |\n|---|---|---|---|---|---|---|---|\n")
        for form in ("eulerian", "tl", "tl25", "enog"):
            rs = [r for r in rows if r["case"] == case and r["formulation"] == form]
            if not rs:
                continue
            by = {r["n"]: r for r in rs}
            cell = lambda n: f"{100 * by[n]['error']:+.1f} %" if n in by else "not run"
            o = order(rs)
            f.write(f"| {LABEL[form]} | {cell(3)} | {cell(4)} | {cell(6)} | {cell(8)} | "
                    f"{'%.2f' % o if o else ''} | {' / '.join(mark(by[n], 'wall_seconds') for n in sorted(by))} | "
                    f"{' / '.join(mark(by[n], 'peak_memory_mb') for n in sorted(by))} |\n")
    f.write("\n### against the complete reference (Timoshenko; with mid-plane stretching for the strip "
            "clamped at both ends)\n")
    for case in ("cantilever", "cc"):
        f.write(f"\n{'cantilever' if case == 'cantilever' else 'clamped-clamped'}: "
                f"{BEST_LABEL[case]} {BEST[case]:.5f} s ({100 * (BEST[case] / rows_ref(case) - 1):+.2f} % "
                f"of Euler-Bernoulli)\n\n| formulation | n = 3 | n = 4 | n = 6 | n = 8 | order | "
                "extrapolated period (n = 4, 6, 8) | its error | its order |\n"
                "|---|---|---|---|---|---|---|---|---|\n")
        for form in ("eulerian", "tl", "tl25", "enog"):
            rs = [dict(r, error=r["period"] / BEST[case] - 1) for r in rows
                  if r["case"] == case and r["formulation"] == form]
            if not rs:
                continue
            by = {r["n"]: r for r in rs}
            cell = lambda n: f"{100 * by[n]['error']:+.1f} %" if n in by else "not run"
            o = order(rs)
            x = richardson(rs)
            f.write(f"| {LABEL[form]} | {cell(3)} | {cell(4)} | {cell(6)} | {cell(8)} | "
                    f"{'%.2f' % o if o else ''} | "
                    + (f"{x[0]:.5f} s | {100 * (x[0] / BEST[case] - 1):+.2f} % | {x[1]:.2f} |\n"
                       if x else "| | |\n"))
    timed = [r for r in rows if r["cpu_seconds"] != ""]
    if timed:
        f.write("\n### runs with CPU time and load (1-minute load average of the 2-core machine)\n\n"
                "| case | formulation | n | width | particles | steps | wall [s] | CPU [s] | load start / mean / end |"
                "\n|---|---|---|---|---|---|---|---|---|\n")
        for r in timed:
            f.write(f"| {r['case']} | {LABEL[r['formulation']]} | {r['n']} | {r['width']} | {r['particles']} | "
                    f"{r['steps']} | {r['wall_seconds']} | {r['cpu_seconds']} | "
                    f"{r['load_start']} / {r['load_mean']} / {r['load_end']} |\n")

checks = []
for run in sorted(glob.glob(os.path.join(root, "checks", "*_*_*", "run*"))):
    try:
        j = json.load(open(os.path.join(run, "summary.json")))
    except (OSError, ValueError):
        continue
    form, case, what = os.path.basename(os.path.dirname(run)).split("_")
    checks.append(dict(check="mirror" if what in ("full", "half") else what, case=case,
                       formulation=form, n=round(H / j["dp"]),
                       width="half" if run.endswith("_half") else "full",
                       speed=0.0285 if what == "slow" else 0.285, particles=j["particles"],
                       steps=j["steps"], wall_seconds=round(j["wall_seconds"], 1),
                       cpu_seconds=load_info(run)["cpu_seconds"],
                       period=f"{j['metrics']['period']['value']:.9f}"))
    ref = (BEST_SLOW if what == "slow" else BEST)[case]
    checks[-1]["error"] = round(j["metrics"]["period"]["value"] / ref - 1, 5)
if checks:
    checks.sort(key=lambda r: (r["check"], r["case"], r["formulation"], r["n"], r["width"]))
    with open(os.path.join(here, "checks.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(checks[0]), lineterminator="\n")
        w.writeheader()
        w.writerows(checks)
    with open(os.path.join(here, "strip_3d.md"), "a") as f:
        f.write("\n### checks: mirror against full width; released at a tenth of the speed\n\n"
                "| check | case | formulation | n | width | speed [m/s] | particles | steps | wall [s] | "
                "CPU [s] | period [s] | error against the complete reference at its speed | "
                "period at 0.285 m/s [s] |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for c in checks:
            same = [r for r in rows if (r["case"], r["formulation"], r["n"]) ==
                    (c["case"], c["formulation"], c["n"])]
            f.write(f"| {c['check']} | {c['case']} | {LABEL[c['formulation']]} | {c['n']} | "
                    f"{c['width']} | {c['speed']} | {c['particles']} | {c['steps']} | "
                    f"{c['wall_seconds']} | {c['cpu_seconds']} | {c['period']} | {100 * c['error']:+.2f} % | "
                    f"{same[0]['period'] if same else ''} |\n")
        for case, form in sorted({(c["case"], c["formulation"]) for c in checks if c["check"] == "slow"}):
            x = richardson([dict(n=c["n"], period=float(c["period"])) for c in checks
                            if (c["check"], c["case"], c["formulation"]) == ("slow", case, form)])
            if x:
                f.write(f"\nAt 0.0285 m/s, {case}, {LABEL[form]}: extrapolated (n = 4, 6, 8) "
                        f"{x[0]:.5f} s, {100 * (x[0] / BEST_SLOW[case] - 1):+.2f} % against "
                        f"{BEST_SLOW[case]:.5f} s, order {x[1]:.2f}.\n")

fig, axes = plt.subplots(2, 2, figsize=(10, 8))
for row, against in enumerate(("Euler-Bernoulli", "complete")):
    for ax, case in zip(axes[row], ("cantilever", "cc")):
        for form in ("eulerian", "tl", "tl25", "enog"):
            rs = [r for r in rows if r["case"] == case and r["formulation"] == form]
            e = [r["error"] if row == 0 else r["period"] / BEST[case] - 1 for r in rs]
            if rs:
                ax.loglog([r["n"] for r in rs], [abs(v) for v in e], "o-", label=LABEL[form])
        ax.axhline(0.05, color="grey", ls="--", lw=0.8)
        ax.set_ylim(0.005, 0.4)
        ax.set_xticks([3, 4, 6, 8])
        ax.set_xticklabels(["3", "4", "6", "8"])
        ax.set_xlabel("particles through the thickness")
        ax.set_ylabel("|period error| vs " + ("Euler-Bernoulli" if row == 0 else BEST_LABEL[case]),
                      fontsize=8 if row else 10)
        ax.set_title("cantilever strip" if case == "cantilever" else "strip clamped at both ends")
        ax.grid(True, which="both", lw=0.3)
axes[0][0].legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(here, "convergence.png"), dpi=110)

n4 = [r for r in rows if r["n"] == 4]
if all(r["run"] is not None for r in n4):  # else the committed tip.png stays
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, case in zip(axes, ("cantilever", "cc")):
        for form in ("eulerian", "tl", "tl25", "enog"):
            rs = [r for r in n4 if r["case"] == case and r["formulation"] == form]
            if not rs:
                continue
            t, y = [], []
            with open(os.path.join(rs[0]["run"], "probes.csv")) as f:
                rd = csv.DictReader(f)
                col = [c for c in rd.fieldnames if c.endswith("_y")][0]
                for row in rd:
                    t.append(float(row["time"]))
                    y.append(float(row[col]) - 0.0025)  # the tracked particle starts at y = dp/2
            ax.plot(t, y, label=LABEL[form])
        ax.set_xlabel("time [s]")
        ax.set_ylabel("deflection [m]")
        ax.set_title(("tip" if case == "cantilever" else "mid-span") + ", 4 through the thickness")
        ax.grid(True, lw=0.3)
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "tip.png"), dpi=110)
print(open(os.path.join(here, "strip_3d.md")).read())
