#!/usr/bin/env python3
"""Slow head-on impact of two equal elastic spheres (solid_contact) against Hertz.

Writes a scene for N particles across (R = 6 mm), relative speed V, formulation and lattice
alignment, runs monosph on one thread and prints one CSV row: contact duration / Hertz,
restitution, smallest distance, peak force and the half-peak width of the force pulse against
Hertz's. Hertz (Johnson 1985, Sect. 11.4): m* = m/2, R* = R/2,
1/E* = 2 (1 - nu^2)/E, delta_max = (15 m* V^2 / (16 E* sqrt(R*)))^(2/5),
t_c = 2.943 delta_max / V = 2.868 (m*^2 / (R* E*^2 V))^(1/5), V the relative approach speed.

Lattice: nodes at domain.min + (k + 1/2) dp. The sphere centres sit at (+-R, 0, 0), R = N dp / 2,
so the outermost particle planes (the pole facets) face each other exactly d_c = dp apart at
t = 0: the spheres' surfaces touch with zero force. align=mid: centres between nodes in y, z;
align=node: centres on nodes in y, z (a different pole facet). align=shells: `fill: shells`, the
spheres filled by concentric shells (body-fitted, round at particle scale: no pole facet).

usage: sphere_study.py N V [formulation] [align] [out_dir] [monosph]
"""
import csv, math, os, subprocess, sys, time

N = int(sys.argv[1]); V = float(sys.argv[2])
form = sys.argv[3] if len(sys.argv) > 3 else "total_lagrangian"
align = sys.argv[4] if len(sys.argv) > 4 else "mid"
out = sys.argv[5] if len(sys.argv) > 5 else f"/tmp/sph_{N}_{V}_{form}_{align}"
exe = sys.argv[6] if len(sys.argv) > 6 else "build/release/monosph"
R, rho, E, nu = 0.006, 1000.0, 1e7, 0.3
dp = 2 * R / N
m0 = rho * 4 / 3 * math.pi * R**3
ms, rs, es = m0 / 2, R / 2, E / (2 * (1 - nu * nu))
tc0 = 2.868 * (ms * ms / (rs * es * es * V)) ** 0.2
lx, ly = (N + 4) * dp, (N // 2 + 4) * dp
sh = 0.5 * dp if align == "node" else 0.0
hg = "\n    hourglass: {alpha: 5}" if form == "total_lagrangian" else ""
hg += "\n    fill: shells" if align == "shells" else ""
body = lambda name, x, v: f"""  - name: {name}
    phase: solid
    material: soft
    continuum: {name}
    shape: {{sphere: {{center: [{x:.10g}, 0, 0], radius: {R}}}}}
    formulation: {form}{hg}
    initial: {{velocity: [{v}, 0, 0]}}
"""
# shells: the contact lasts up to ~1.3 t_c; then 3 dp of separation at V (beyond the support)
end_time = 1.35 * tc0 if align != "shells" else 1.4 * tc0 + 3 * dp / V
scene = f"""name: sphere_study
dimension: 3
dp: {dp:.12g}
kernel: {{type: cubic_spline, h_factor: 1.3}}
domain: {{min: [{-lx:.12g}, {-ly + sh:.12g}, {-ly + sh:.12g}], max: [{lx:.12g}, {ly + sh:.12g}, {ly + sh:.12g}]}}
materials:
  soft: {{density: {rho}, bulk_modulus: 8.333333333333333e6, shear_modulus: 3.846153846153846e6}}
bodies:
{body("left", -R, V / 2)}{body("right", R, -V / 2)}solid_contact: {{distance: 1.0, friction: 0}}
end_time: {end_time:.6g}
time_step: {{cfl: 0.3}}
output: {{every: 0}}
probes:
  every: {tc0 / 500:.6g}
  list:
    - {{name: left_vx, type: mean, field: velocity.x, body: left}}
    - {{name: right_vx, type: mean, field: velocity.x, body: right}}
    - {{name: left_p, type: momentum, body: left}}
    - {{name: force, type: solid_contact_force, body: left}}
    - {{name: pairs, type: solid_contact_pairs}}
    - {{name: near, type: solid_contact_neighbours}}
    - {{name: min_distance, type: min_distance}}
"""
os.makedirs(out, exist_ok=True)
open(out + "/scene.yaml", "w").write(scene)
t0 = time.time()
r = subprocess.run([exe, "run", out + "/scene.yaml", "--out", out + "/run", "--quiet",
                    "--threads", os.environ.get("THREADS", "1")], capture_output=True, text=True)
wall = time.time() - t0
rows = list(csv.DictReader(open(out + "/run/probes.csv")))
col = lambda k: [float(x[k]) for x in rows]
t, f, pairs = col("time"), col("force_x"), col("pairs")
m = col("left_p_x")[0] / (V / 2)
tc = 2.868 * ((m / 2) ** 2 / (rs * es * es * V)) ** 0.2  # mass from the particles
on = [k for k in range(len(t)) if pairs[k] > 0]
end = 0.5 * (t[on[-1]] + t[on[-1] + 1]) if on and on[-1] + 1 < len(t) else float("nan")
peak = max(abs(x) for x in f)
first = next(k for k in range(len(t)) if abs(f[k]) > 1e-3 * peak)
last = max(k for k in range(len(t)) if abs(f[k]) > 1e-3 * peak)
dur_thr = t[last] - t[first]
def half_width(ts, fs):  # time between the crossings of half the peak force (linear interpolation)
    fm = max(fs); k0 = next(k for k in range(len(fs)) if fs[k] >= fm / 2)
    k1 = max(k for k in range(len(fs)) if fs[k] >= fm / 2)
    cross = lambda i, j: ts[i] + (fm / 2 - fs[i]) * (ts[j] - ts[i]) / (fs[j] - fs[i])
    return cross(k1, k1 + 1) - cross(k0 - 1, k0)
# Hertz pulse by integrating m* d'' = -(4/3) E* sqrt(R*) d^1.5 (for its half-peak width)
kh, d, vv, hs, hf = 4 / 3 * es * math.sqrt(rs), 0.0, V, [0.0], [0.0]
while d >= 0:
    vv -= kh * d**1.5 / (m / 2) * tc / 20000; d += vv * tc / 20000
    hs.append(hs[-1] + tc / 20000); hf.append(kh * max(d, 0) ** 1.5)
fwhm = half_width(t, [abs(x) for x in f]) / half_width(hs, hf)
e = (col("right_vx")[-1] - col("left_vx")[-1]) / V
fh = 4 / 3 * es * math.sqrt(rs) * ((15 * ms * V**2 / (16 * es * math.sqrt(rs))) ** 0.4) ** 1.5
print(f"{N},{dp:.4g},{len(rows) and r.returncode},{form},{align},{V},{m:.5g},{tc:.5g},"
      f"{end:.5g},{end / tc:.4f},{dur_thr / tc:.4f},{e:.4f},{min(col('min_distance')):.3f},"
      f"{peak / fh:.3f},{fwhm:.4f},{col('near')[-1]:.0f},{wall:.0f}")
