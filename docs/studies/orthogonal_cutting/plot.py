#!/usr/bin/env python3
"""Measured and simulated cutting force, feed force and chip ratio of cases/orthogonal_cutting.

Usage: plot.py OUT.png STUDY.csv[:LABEL] ...  (study.csv files of `monosph study`, e.g. one per dp)
Reads the measurement from ../shared/reference/data/cutting_ti6al4v_ducobu2024.csv, prints a
markdown table (simulated value and error per condition, mean |error| per quantity) and draws bars
like the reference's figures. Needs Debian's python3-matplotlib.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
REF = os.path.join(HERE, "../../../../shared/reference/data/cutting_ti6al4v_ducobu2024.csv")
QUANTITIES = [("cutting_force", "exp_Fc_N_per_mm", "Fc (N/mm)", 1e-3),
              ("feed_force", "exp_Ff_N_per_mm", "Ff (N/mm)", 1e-3),
              ("chip_ratio", "exp_chip_ratio", "chip thickness ratio", 1.0),
              ("chip_ratio_flow", "exp_chip_ratio", "chip ratio by mass flux", 1.0)]


def read_reference():
    with open(REF) as f:
        rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]
    return {(int(r["vc_m_per_min"]), round(float(r["h_um"]))): r for r in rows}


def read_study(path):
    out = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            key = (int(float(r["variables.vc"])), round(float(r["variables.h"]) * 1e6))
            out[key] = r
    return out


def main():
    png, studies = sys.argv[1], sys.argv[2:]
    ref = read_reference()
    runs = []
    for s in studies:
        path, _, label = s.partition(":")
        runs.append((label or os.path.basename(path), read_study(path)))
    keys = sorted(set().union(*[set(r) for _, r in runs]))
    quantities = [q for q in QUANTITIES  # the flow chip ratio where a study has it
                  if q[0] != "chip_ratio_flow"
                  or any(q[0] + "_value" in r for _, rows in runs for r in rows.values())]
    fig, axes = plt.subplots(1, len(quantities), figsize=(5 * len(quantities), 4.5))
    width = 0.8 / (1 + len(runs))
    for ax, (name, col, title, scale) in zip(axes, quantities):
        xs = range(len(keys))
        ax.bar([x - 0.4 + width / 2 for x in xs], [float(ref[k][col]) for k in keys], width,
               label="measured", color="black")
        for j, (label, rows) in enumerate(runs):
            vals = [float(rows[k][name + "_value"]) * scale
                    if k in rows and rows[k]["status"] == "completed"
                    and rows[k].get(name + "_value") else 0 for k in keys]
            ax.bar([x - 0.4 + width * (j + 1.5) for x in xs], vals, width, label=label)
        ax.set_xticks(list(xs))
        ax.set_xticklabels([f"{vc} m/min\n{h} um" for vc, h in keys], fontsize=8)
        ax.set_title(title)
    axes[0].legend()
    fig.tight_layout()
    fig.savefig(png, dpi=90)
    # Markdown table: per run and condition the simulated values and errors.
    for label, rows in runs:
        print(f"\n{label}\n")
        flow = any(r.get("chip_ratio_flow_value") for r in rows.values())
        qs = [q for q in quantities if q[0] != "chip_ratio_flow" or flow]
        print("| vc m/min | h um | Fc | err | Ff | err | chip ratio | err |"
              + (" chip ratio (flow) | err |" if flow else ""))
        print("|---|---|---|---|---|---|---|---|" + ("---|---|" if flow else ""))
        sums, count = [0.0] * len(qs), 0
        for k in keys:
            if k not in rows or rows[k]["status"] != "completed":
                what = ("stopped at t = " + rows[k]["status"].split(" at t = ")[-1].rstrip(")") + " s"
                        if k in rows else "not run")
                print(f"| {k[0]} | {k[1]} | {what} | | | | | |" + (" | |" if flow else ""))
                continue
            cells, count = [], count + 1
            for q, (name, col, _, scale) in enumerate(qs):
                sim, meas = float(rows[k][name + "_value"]) * scale, float(ref[k][col])
                sums[q] += abs(sim - meas) / meas
                cells.append(f"{sim:.3g} ({meas:.3g}) | {100 * (sim - meas) / meas:+.1f} %")
            print(f"| {k[0]} | {k[1]} | " + " | ".join(cells) + " |")
        if count:
            print("| mean \\|error\\| | | | " + " | | ".join(f"{100 * s / count:.1f} %" for s in sums)
                  + " |")


if __name__ == "__main__":
    main()
