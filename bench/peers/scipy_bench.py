"""scipy.interpolate.BSpline on the workload of src/main.rs; prints the same columns."""
import time

import numpy as np
from scipy.interpolate import BSpline

N, M = 1000, 1_000_000
x = np.arange(N, dtype=float)
c = np.c_[x, np.sin(x * 0.37), np.cos(x * 0.11)]
k = np.r_[[0.0] * 4, np.arange(1, N - 3) / (N - 3), [1.0] * 4]
spl = BSpline(k, c, 3)
dspl = spl.derivative()
s = 0x9E3779B97F4A7C15
random = np.empty(M)
mask = (1 << 64) - 1
for i in range(M):
    s ^= (s << 13) & mask
    s ^= s >> 7
    s ^= (s << 17) & mask
    random[i] = (s >> 11) / float(1 << 53)
sorted_ = np.linspace(0.0, 1.0, M)


def best(f):
    t = float("inf")
    for _ in range(5):
        a = time.perf_counter()
        v = f()
        t = min(t, time.perf_counter() - a)
    return t * 1e9 / M, v


for what, f in [("point, random order", lambda: spl(random)[:, 1].sum()),
                ("point, sorted batch", lambda: spl(sorted_)[:, 1].sum()),
                ("first derivative, sorted", lambda: dspl(sorted_)[:, 1].sum())]:
    ns, check = best(f)
    print(f"scipy {__import__('scipy').__version__}\t{what}\t{ns:.2f}\t{check:.9e}")
