"""The curve rows of bench.py alone, best of 9 calls each (issue 20's Python goals): a cubic
3-D B-spline with 1000 and 10⁵ control points at 10⁶ sorted parameters and at random ones
(10⁶, or 2·10⁴ on 10⁵ control points, where scipy walks the knots), splinekit beside scipy in
one process. Run it three times on a quiet machine; the README quotes the ranges.

    python bench/python/curve_rows.py
"""

import numpy as np
from scipy.interpolate import BSpline

import splinekit as sk
from bench import best, clamped_uniform


def main():
    rng = np.random.default_rng(1)
    m = 1_000_000
    for n in (1000, 100_000):
        knots, cp = clamped_uniform(n), rng.normal(size=(n, 3))
        ours, ref = sk.BSpline(knots, cp, 3), BSpline(knots, cp, 3)
        for order in ("sorted", "random"):
            count = m if order == "sorted" or n <= 1000 else m // 50
            t = np.linspace(0.0, 1.0, count) if order == "sorted" else rng.random(count)
            np.testing.assert_allclose(ours(t), ref(t), atol=1e-10)
            t_ours, _ = best(lambda: ours(t), 9)
            t_ref, _ = best(lambda: ref(t), 5 if count == m else 3)
            print(f"{n} control points, {count} {order} parameters: splinekit {t_ours / count * 1e9:6.2f} ns, "
                  f"scipy {t_ref / count * 1e9:8.1f} ns ({t_ref / t_ours:5.1f}x)", flush=True)


if __name__ == "__main__":
    main()
