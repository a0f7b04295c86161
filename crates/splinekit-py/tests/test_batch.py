"""fit_many and evaluate_many return exactly what a loop of single calls returns, on any
number of threads, and refuse bad entries with the single call's message, indexed."""

import re

import numpy as np
import pytest

import splinekit as sk


def point_sets(count, seed=1, dimension=3):
    rng = np.random.default_rng(seed)
    return [rng.normal(size=(int(rng.integers(12, 80)), dimension)).cumsum(axis=0) for _ in range(count)]


def same_curve(a, b):
    assert type(a) is type(b) and a == b
    for name in ("knots", "control_points"):
        assert getattr(a, name).tobytes() == getattr(b, name).tobytes()
    assert a.fit_report == b.fit_report


OPTIONS = [
    dict(degree=3, n_control_points=8),
    dict(degree=2, n_control_points=6, params="centripetal", knots="uniform"),
    dict(degree=3, n_control_points=7, closed=True),
    dict(degree=3, n_control_points=9, fix_ends=True, params="uniform"),
    dict(degree=3, knots=[0, 0, 0, 0, 0.3, 0.5, 0.8, 1, 1, 1, 1]),
]


@pytest.mark.parametrize("options", OPTIONS, ids=lambda o: ",".join(f"{k}={v}" for k, v in o.items())[:40])
@pytest.mark.parametrize("threads", [None, 1, 2, 3])
def test_fit_many_is_the_loop(options, threads):
    sets = point_sets(40)
    loop = [sk.fit(p, **options) for p in sets]
    for got, want in zip(sk.fit_many(sets, **options, threads=threads), loop, strict=True):
        same_curve(got, want)


def test_fit_many_takes_shared_arrays_and_any_dimension():
    rng = np.random.default_rng(3)
    sets = [rng.normal(size=(30, d)) for d in (1, 2, 3, 4, 2)]
    weights = rng.uniform(0.5, 2.0, 30)
    params = np.sort(rng.uniform(0, 1, 30))
    params[0], params[-1] = 0.0, 1.0
    options = dict(degree=3, n_control_points=10, weights=weights, params=params)
    for got, want in zip(sk.fit_many(sets, **options), [sk.fit(p, **options) for p in sets], strict=True):
        same_curve(got, want)
    stacked = rng.normal(size=(5, 25, 3))  # a 3-D array is a sequence of point sets
    for got, want in zip(sk.fit_many(stacked, 3, 6), [sk.fit(p, 3, 6) for p in stacked], strict=True):
        same_curve(got, want)
    assert sk.fit_many([], 3, 6) == []


def single_error(call):
    with pytest.raises(ValueError) as e:
        call()
    return str(e.value)


def test_fit_many_refuses_with_the_single_calls_message_indexed():
    sets = point_sets(5)
    bad = sets[:3] + [sets[3][:4]] + sets[4:]
    message = single_error(lambda: sk.fit(bad[3], 3, 8))
    with pytest.raises(ValueError, match="^" + re.escape(f"point_sets[3]: {message}") + "$"):
        sk.fit_many(bad, 3, 8)
    flat = sets[:1] + [np.zeros(10)]
    message = single_error(lambda: sk.fit(flat[1], 3, 8))
    with pytest.raises(ValueError, match="^" + re.escape(f"point_sets[1]: {message}") + "$"):
        sk.fit_many(flat, 3, 8)
    with pytest.raises(ValueError, match=r"^degree: must be between 1 and 64, got 0$"):
        sk.fit_many(sets, 0, 8)
    with pytest.raises(ValueError, match=r"^threads: must be at least 1, got 0$"):
        sk.fit_many(sets, 3, 8, threads=0)
    nan = sets[:2] + [np.full((10, 2), np.nan)]
    message = single_error(lambda: sk.fit(nan[2], 3, 5))
    assert message == "points[0][0]: coordinate is not finite (NaN)"
    with pytest.raises(ValueError, match="^" + re.escape(f"point_sets[2]: {message}") + "$"):
        sk.fit_many(nan, 3, 5)


def shapes_and_params():
    rng = np.random.default_rng(7)
    curve = sk.fit(rng.normal(size=(200, 3)).cumsum(axis=0), 3, 40)
    torus = sk.load({"type": "torus"})
    circle = sk.load({"type": "circle"})
    surface = sk.BSplineSurface([0, 0, 0, 0.5, 1, 1, 1], [0, 0, 1, 1], rng.normal(size=(4, 2, 3)), 2, 1)
    shapes = [curve, circle, curve, surface, torus, sk.Bezier(rng.normal(size=(5, 2)))]
    params = [
        rng.uniform(0, 1, 10_000),  # several chunks of one curve
        np.linspace(-7, 7, 333),  # closed: wraps around
        0.25,  # a number: shape (D,)
        (np.linspace(0, 1, 17), np.linspace(0, 1, 5)),
        (np.linspace(0, 2 * np.pi, 9), np.linspace(0, 2 * np.pi, 11)),
        [],
    ]
    return shapes, params


@pytest.mark.parametrize("nu", [0, 1, 3])
@pytest.mark.parametrize("threads", [None, 1, 2])
def test_evaluate_many_is_the_loop(nu, threads):
    shapes, params = shapes_and_params()
    loop = [s(*p) if isinstance(s, sk.Surface) else s(p, nu) for s, p in zip(shapes, params)]
    got = sk.evaluate_many(shapes, params, nu=nu, threads=threads)
    assert len(got) == len(loop)
    for g, w in zip(got, loop):
        assert g.shape == w.shape and g.dtype == w.dtype and g.flags.c_contiguous
        assert g.tobytes() == w.tobytes()


@pytest.mark.parametrize("nu", [0, 2])
def test_large_outputs_are_the_small_calls(nu):
    # A large output is written chunk by chunk (2048 rows): the same values as small
    # calls, over whole chunks and an odd tail, on one thread or many (evaluate_many splits
    # a large curve into the same chunks).
    rng = np.random.default_rng(7)
    knots = np.concatenate([[0.0] * 3, np.linspace(0.0, 1.0, 998), [1.0] * 3])
    curve = sk.BSpline(knots, rng.normal(size=(1000, 3)), 3)
    t = np.concatenate([np.linspace(0.0, 1.0, 150_000), rng.random(50_003)])
    large = curve(t, nu)
    assert large.nbytes >= 4 << 20 and large.flags.c_contiguous
    small = np.concatenate([curve(t[i : i + 5000], nu) for i in range(0, t.size, 5000)])
    assert large.tobytes() == small.tobytes()
    derivatives = curve.derivatives(t, 2)
    pieces = [curve.derivatives(t[i : i + 5000], 2) for i in range(0, t.size, 5000)]
    assert derivatives.tobytes() == np.concatenate(pieces).tobytes()
    for threads in (1, 2):
        (many,) = sk.evaluate_many([curve], [t], nu=nu, threads=threads)
        assert many.tobytes() == large.tobytes()


def test_evaluate_many_refuses_with_the_single_calls_message_indexed():
    shapes, params = shapes_and_params()
    outside = list(params)
    outside[0] = np.array([0.5, 1.5])
    message = single_error(lambda: shapes[0](outside[0]))
    with pytest.raises(ValueError, match="^" + re.escape(f"params[0]: {message}") + "$"):
        sk.evaluate_many(shapes, outside)
    outside = list(params)
    outside[3] = (np.array([0.5]), np.array([2.0]))
    message = single_error(lambda: shapes[3](*outside[3]))
    with pytest.raises(ValueError, match="^" + re.escape(f"params[3]: {message}") + "$"):
        sk.evaluate_many(shapes, outside)
    with pytest.raises(ValueError, match=r"^params: expected one entry per shape \(6\), got 5$"):
        sk.evaluate_many(shapes, params[:5])
    with pytest.raises(ValueError, match=r"^shapes\[1\]: expected a splinekit curve or surface, got str$"):
        sk.evaluate_many([shapes[0], "circle"], [0.5, 0.5])
    with pytest.raises(ValueError, match=r"^params\[3\]: expected a pair \(u, v\) of parameters for a surface$"):
        sk.evaluate_many(shapes, params[:3] + [0.5] + params[4:])
    with pytest.raises(ValueError, match=r"^params\[0\]: nu: 65 is more than the limit of 64$"):
        sk.evaluate_many(shapes, params, nu=65)


def test_unaligned_arrays_are_read_like_any_other():
    # Arrays unpickled from out-of-band buffers or received by Dask workers may start at
    # any byte; they are copied to aligned memory, never refused or misread.
    def unaligned(values):
        values = np.ascontiguousarray(values, dtype=np.float64)
        raw = np.zeros(values.nbytes + 1, dtype=np.uint8)
        shifted = raw[1:].view(np.float64).reshape(values.shape)
        shifted[...] = values
        assert not shifted.flags.aligned and shifted.flags.c_contiguous
        return shifted

    curve = sk.fit(np.random.default_rng(8).normal(size=(100, 3)).cumsum(axis=0), 3, 12)
    t = np.random.default_rng(2).uniform(0, 1, 5000)
    assert curve(unaligned(t)).tobytes() == curve(t).tobytes()
    points = np.random.default_rng(3).normal(size=(60, 2))
    assert sk.fit(unaligned(points), 3, 9) == sk.fit(points, 3, 9)
    assert sk.fit_many([unaligned(points)], 3, 9) == [sk.fit(points, 3, 9)]
    assert sk.evaluate_many([curve], [unaligned(t)])[0].tobytes() == curve(t).tobytes()
