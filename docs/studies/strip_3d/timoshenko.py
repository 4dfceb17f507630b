#!/usr/bin/env python3
"""First bending period of the 3D strips of cases/oscillating_strip_3d by Euler-Bernoulli theory
(the reference of the scenes) and by Timoshenko beam theory (shear deformation and rotary
inertia; shear coefficient of a rectangle kappa = 10(1+nu)/(12+11nu), Cowper 1966, J. Appl. Mech.
33, 335-340, Table 1), the latter solved by finite elements (linear elements, one-point shear
integration against locking; 400 elements: within 1e-4 of 2000).
The strip clamped at both ends has immovable ends: its deflection stretches the mid-plane, and the
axial force N = EA/(2L) int w'^2 dx hardens it (Woinowsky-Krieger 1950, J. Appl. Mech. 17, 35-36,
for hinged ends). The one-mode Galerkin projection of rho A w_tt + EI w_xxxx - N w_xx = 0 on the
clamped-clamped mode phi (phi(L/2) = 1) is the Duffing equation q'' + w0^2 q + beta q^3 = 0,
beta = E I1^2 / (2 L rho I0), I0 = int phi^2, I1 = int phi'^2; started as the scenes are (q = 0,
q' = the mid-span speed v), its period comes from the ODE (stretching_ratio)."""
import numpy as np
from scipy.integrate import quad, solve_ivp
from scipy.linalg import eigh

K, mu, rho = 3.25e6, 0.715e6, 1000.0
E = 9 * K * mu / (3 * K + mu)
nu = (3 * K - 2 * mu) / (2 * (3 * K + mu))
G = mu
h = b = 0.02
A, I = b * h, b * h**3 / 12
kappa = 10 * (1 + nu) / (12 + 11 * nu)


def timoshenko_period(L, clamped_both, ne=4000, Em=E):
    le = L / ne
    n = ne + 1
    Kg = np.zeros((2 * n, 2 * n))
    Mg = np.zeros((2 * n, 2 * n))
    for e in range(ne):
        d = [2 * e, 2 * e + 1, 2 * e + 2, 2 * e + 3]  # w1, th1, w2, th2
        # bending: Em I (th' )^2 ; shear: kappa G A (w' - th)^2 at the midpoint
        kb = Em * I / le * np.array([[0, 0, 0, 0], [0, 1, 0, -1], [0, 0, 0, 0], [0, -1, 0, 1]])
        B = np.array([-1 / le, -0.5, 1 / le, -0.5])
        ks = kappa * G * A * le * np.outer(B, B)
        mw = rho * A * le / 6 * np.array([[2, 1], [1, 2]])
        mt = rho * I * le / 6 * np.array([[2, 1], [1, 2]])
        me = np.zeros((4, 4))
        me[np.ix_([0, 2], [0, 2])] = mw
        me[np.ix_([1, 3], [1, 3])] = mt
        Kg[np.ix_(d, d)] += kb + ks
        Mg[np.ix_(d, d)] += me
    fixed = [0, 1] + ([2 * n - 2, 2 * n - 1] if clamped_both else [])
    free = [k for k in range(2 * n) if k not in fixed]
    w2 = eigh(Kg[np.ix_(free, free)], Mg[np.ix_(free, free)], eigvals_only=True,
              subset_by_index=[0, 0])[0]
    return 2 * np.pi / np.sqrt(w2)


def euler_bernoulli(L, kl, Em=E):
    return 2 * np.pi / (kl**2 * np.sqrt(Em * h**2 / (12 * rho * L**4)))


def stretching_ratio(L, kl, v, Em=E):
    """Period with mid-plane stretching over the linear period (clamped-clamped, released with the
    mid-span speed v), and the amplitude."""
    k = kl / L
    s = (np.cosh(kl) - np.cos(kl)) / (np.sinh(kl) - np.sin(kl))
    phi = lambda x: np.cosh(k * x) - np.cos(k * x) - s * (np.sinh(k * x) - np.sin(k * x))
    d1 = lambda x: k * (np.sinh(k * x) + np.sin(k * x) - s * (np.cosh(k * x) - np.cos(k * x)))
    d2 = lambda x: k * k * (np.cosh(k * x) + np.cos(k * x) - s * (np.sinh(k * x) + np.sin(k * x)))
    c = phi(L / 2)
    i0, i1, i2 = (quad(lambda x: (g(x) / c) ** 2, 0, L, limit=200)[0] for g in (phi, d1, d2))
    w0 = np.sqrt(Em * I * i2 / (rho * A * i0))
    beta = Em * i1**2 / (2 * L * rho * i0)
    up = lambda t, y: y[0]
    up.direction = 1
    sol = solve_ivp(lambda t, y: [y[1], -w0**2 * y[0] - beta * y[0] ** 3], [1e-9, 8 * np.pi / w0],
                    [v * 1e-9, v], events=up, rtol=1e-11, atol=1e-14, max_step=0.01 / w0)
    te = sol.t_events[0]
    period = (te[-1] - te[0]) / (len(te) - 1)
    return period * w0 / (2 * np.pi), np.max(np.abs(sol.y[0]))


if __name__ == "__main__":
    print(f"E = {E:.6g} Pa, nu = {nu:.4f}, kappa = {kappa:.4f}")
    for name, L, kl, cc in [("cantilever", 0.2, 1.87510407, False),
                            ("clamped-clamped", 0.4, 4.73004074, True)]:
        teb = euler_bernoulli(L, kl)
        tt = timoshenko_period(L, cc, ne=400)
        tp = euler_bernoulli(L, kl, E / (1 - nu**2))
        print(f"{name}: Euler-Bernoulli {teb:.5f} s, Timoshenko {tt:.5f} s "
              f"({100 * (tt / teb - 1):+.2f} %), plate E/(1-nu^2) {tp:.5f} s "
              f"({100 * (tp / teb - 1):+.2f} %)")
    tt = timoshenko_period(0.4, True, ne=400)
    teb = euler_bernoulli(0.4, 4.73004074)
    for v in (0.285, 0.0285):
        r, a = stretching_ratio(0.4, 4.73004074, v)
        print(f"clamped-clamped, mid-span speed {v} m/s: amplitude {a:.5f} m = {a / h:.3f} h, "
              f"stretching T/T0 = {r:.4f} ({100 * (r - 1):+.2f} %); Euler-Bernoulli with "
              f"stretching {teb * r:.5f} s, Timoshenko with stretching {tt * r:.5f} s "
              f"({100 * (tt * r / teb - 1):+.2f} % of Euler-Bernoulli)")
