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


def best(f, count=M):
    """Best of 5 calls of f, in ns per element; f's output array is returned for the checksum,
    taken outside the timing as src/main.rs does."""
    t = float("inf")
    for _ in range(5):
        a = time.perf_counter()
        v = f()
        t = min(t, time.perf_counter() - a)
    return t * 1e9 / count, v


# Checksums as src/main.rs: the sum of every coordinate for points, of y for derivatives.
for what, f, check in [("point, random order", lambda: spl(random), lambda v: v.sum()),
                       ("point, sorted batch", lambda: spl(sorted_), lambda v: v.sum()),
                       ("first derivative, sorted", lambda: dspl(sorted_), lambda v: v[:, 1].sum())]:
    ns, v = best(f)
    check = check(v)
    print(f"scipy {__import__('scipy').__version__}\t{what}\t{ns:.2f}\t{check:.9e}")

# The same curve with 10⁵ control points at the first 2·10⁴ random parameters.
NL, ML = 100_000, 20_000
xl = np.arange(NL, dtype=float)
large = BSpline(np.r_[[0.0] * 4, np.arange(1, NL - 3) / (NL - 3), [1.0] * 4],
                np.c_[xl, np.sin(xl * 0.37), np.cos(xl * 0.11)], 3)
ns, v = best(lambda: large(random[:ML]), ML)
print(f"scipy {__import__('scipy').__version__}\tpoint, random, 10^5 cp\t{ns:.2f}\t{v.sum():.9e}")

# Splipy: the surface workload of src/main.rs (bicubic, 100 × 100 control points, points and
# unit normals on a 300 × 300 grid).
try:
    import splipy
    from splipy import BSplineBasis, Surface as SplipySurface
except ImportError:
    splipy = None
if splipy is not None:
    G = 300
    knots = np.r_[[0.0] * 4, np.arange(1, 97) / 97.0, [1.0] * 4]
    basis = BSplineBasis(4, knots)
    i, j = np.meshgrid(np.arange(100.0), np.arange(100.0), indexing="ij")
    net = np.stack([i, j, np.sin(i * 0.3) * np.cos(j * 0.2)], axis=-1)
    # Splipy orders control points with the first parameter running fastest.
    surf = SplipySurface(basis, basis, net.transpose(1, 0, 2).reshape(-1, 3))
    g = np.linspace(0.0, 1.0, G)

    def run():
        p = surf(g, g)
        n = surf.normal(g, g)
        return p[..., 2].sum() + n[..., 2].sum()

    t = float("inf")
    for _ in range(5):
        a = time.perf_counter()
        v = run()
        t = min(t, time.perf_counter() - a)
    print(f"splipy {splipy.__version__}\tsurface grid: points + normals\t{t * 1e9 / G / G:.2f}\t{v:.9e}")
