#!/usr/bin/env python3
"""First bending period of the 3D strips of cases/oscillating_strip_3d by Euler-Bernoulli theory
(the reference of the scenes) and by Timoshenko beam theory (shear deformation and rotary
inertia; shear coefficient of a rectangle kappa = 10(1+nu)/(12+11nu), Cowper 1966, J. Appl. Mech.
33, 335-340, Table 1), the latter solved by finite elements (linear elements, one-point shear
integration against locking; 400 elements: within 1e-4 of 2000)."""
import numpy as np
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
