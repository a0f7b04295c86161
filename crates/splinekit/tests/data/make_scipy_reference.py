"""Reference values from scipy.interpolate for splinekit's tests.

Run:  pip install scipy numpy && python3 make_scipy_reference.py > scipy_reference.json
The data are generated here (seeded) and stored in the JSON with the expected results,
so the Rust tests need neither Python nor scipy.
"""
import json
import sys

import numpy as np
import scipy
from scipy.interpolate import BSpline, make_interp_spline, make_lsq_spline

rng = np.random.default_rng(20261122)
cases = {"scipy_version": scipy.__version__, "lsq": [], "interp": [], "eval": []}


def clamped(k, interior, a=0.0, b=1.0):
    return np.r_[[a] * (k + 1), interior, [b] * (k + 1)]


def lsq_case(name, x, y, t, k, w=None):
    spl = make_lsq_spline(x, y, t, k=k, w=w)
    cases["lsq"].append({
        "name": name, "degree": k, "knots": list(map(float, t)), "params": list(map(float, x)),
        "points": [list(map(float, r)) for r in y],
        "weights": None if w is None else list(map(float, w)),
        "control_points": [list(map(float, r)) for r in spl.c],
    })


# 1. Cubic, uniform knots, noisy circle-like data.
x = np.linspace(0, 1, 200)
y = np.c_[np.cos(2 * np.pi * x), np.sin(2 * np.pi * x)] + 0.01 * rng.standard_normal((200, 2))
lsq_case("cubic uniform noisy", x, y, clamped(3, np.linspace(0, 1, 12)[1:-1]), 3)
# 2. Quadratic, non-uniform knots, random sorted parameters, 3-D.
x = np.sort(rng.uniform(0, 1, 300)); x[0], x[-1] = 0.0, 1.0
y = np.c_[x ** 2, np.sin(5 * x), np.exp(-x)] + 0.001 * rng.standard_normal((300, 3))
lsq_case("quadratic nonuniform 3d", x, y, clamped(2, np.sort(rng.uniform(0.05, 0.95, 15))), 2)
# 3. Weighted quintic.
x = np.linspace(0, 1, 120)
y = np.c_[np.sin(3 * x), np.cos(7 * x)]
w = rng.uniform(0.1, 2.0, 120)
lsq_case("quintic weighted", x, y, clamped(5, np.linspace(0, 1, 9)[1:-1]), 5, w)
# 4. Ill-conditioned: knots clustered near 0.5, few samples per span.
interior = 0.5 + np.array([-0.3, -0.1, -0.01, -0.001, -0.0001, 0.0001, 0.001, 0.01, 0.1, 0.3])
x = np.sort(np.r_[np.linspace(0, 1, 60), 0.5 + np.linspace(-0.0002, 0.0002, 30)])
y = np.c_[np.tanh(40 * (x - 0.5)), x]
lsq_case("cubic clustered knots", x, y, clamped(3, interior), 3)

# Interpolation on given knots.
for k, m in [(3, 10), (2, 9), (5, 14)]:
    x = np.sort(rng.uniform(0, 1, m)); x[0], x[-1] = 0.0, 1.0
    y = rng.standard_normal((m, 2))
    t = clamped(k, [x[j:j + k].mean() for j in range(1, m - k)])
    spl = make_interp_spline(x, y, k=k, t=t)
    cases["interp"].append({"degree": k, "knots": list(map(float, t)), "params": list(map(float, x)),
                            "points": [list(map(float, r)) for r in y],
                            "control_points": [list(map(float, r)) for r in spl.c]})

# Evaluation with derivatives on non-uniform, unclamped knots.
for k in [1, 2, 3, 4, 7]:
    n = k + 8
    t = np.sort(rng.uniform(0, 10, n + k + 1))
    c = rng.standard_normal((n, 3))
    spl = BSpline(t, c, k, extrapolate=False)
    xs = np.linspace(t[k], t[n], 57)[1:-1]
    cases["eval"].append({"degree": k, "knots": list(map(float, t)), "control_points": [list(map(float, r)) for r in c],
                          "params": list(map(float, xs)),
                          "derivatives": [[list(map(float, spl(xx, nu=d))) for d in range(0, min(k, 3) + 1)] for xx in xs]})

json.dump(cases, sys.stdout, indent=0)
