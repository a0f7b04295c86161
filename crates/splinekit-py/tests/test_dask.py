"""splinekit inside Dask: dask.array.map_blocks, dask.bag, and a two-worker
dask.distributed LocalCluster (separate processes, so every curve travels by pickle).
Whatever runs where, the results are bit for bit those of one process."""

import logging

import dask
import dask.array as da
import dask.bag as db
import numpy as np
import pytest
from dask.distributed import Client, LocalCluster, get_task_stream

import splinekit as sk

# The sizes of issue 21: 10⁷ parameters, 10⁴ point sets.
PARAMETERS = 10_000_000
POINT_SETS = 10_000


def curve():
    rng = np.random.default_rng(2)
    return sk.fit(rng.normal(size=(400, 3)).cumsum(axis=0), 3, 60)


def point_sets(count):
    rng = np.random.default_rng(4)
    return [rng.normal(size=(40, 3)).cumsum(axis=0) for _ in range(count)]


def same_bits(a, b):
    return a.shape == b.shape and a.dtype == b.dtype and np.array_equal(a.view(np.uint64), b.view(np.uint64))


def evaluate_blocks(c, t, chunk):
    """c(t) as a dask array: one map_blocks task per chunk of the parameters t."""
    blocks = da.from_array(t, chunks=chunk)
    return blocks.map_blocks(c, dtype=np.float64, new_axis=1, chunks=(blocks.chunks[0], (c.dimension,)))


def fits(partition):
    return sk.fit_many(partition, 3, 8, threads=1)


def test_map_blocks_with_threads():
    c = curve()
    t = np.random.default_rng(1).uniform(*c.domain, 1_000_000)
    with dask.config.set(scheduler="threads", num_workers=2):
        got = evaluate_blocks(c, t, 100_000).compute()
    assert same_bits(got, c(t))


def test_bag_with_threads():
    sets = point_sets(500)
    with dask.config.set(scheduler="threads", num_workers=2):
        got = db.from_sequence(sets, npartitions=4).map_partitions(fits).compute()
        single = db.from_sequence(sets, npartitions=4).map(lambda p: sk.fit(p, 3, 8)).compute()
    want = [sk.fit(p, 3, 8) for p in sets]
    assert got == want and single == want


@pytest.fixture(scope="module")
def client():
    cluster = LocalCluster(
        n_workers=2,
        threads_per_worker=1,
        processes=True,
        dashboard_address=None,
        silence_logs=logging.ERROR,
    )
    with cluster, Client(cluster) as c:
        yield c


def test_distributed_evaluation_of_ten_million_parameters(client):
    c = curve()
    # The parameters are made on the workers (no 80 MB graph to ship).
    t = da.linspace(*c.domain, PARAMETERS, chunks=PARAMETERS // 8)
    points = t.map_blocks(c, dtype=np.float64, new_axis=1, chunks=(t.chunks[0], (c.dimension,)))
    with get_task_stream(client) as stream:
        got, params = dask.compute(points, t)
    assert len({task["worker"] for task in stream.data}) == 2, "both workers evaluated"
    assert params.shape == (PARAMETERS,)
    assert same_bits(got, c(params))


def test_distributed_fit_of_ten_thousand_point_sets(client):
    sets = point_sets(POINT_SETS)
    with get_task_stream(client) as stream:
        got = db.from_sequence(sets, npartitions=8).map_partitions(fits).compute()
    assert len({task["worker"] for task in stream.data}) == 2, "both workers fitted"
    want = sk.fit_many(sets, 3, 8)
    assert len(got) == len(want) == POINT_SETS
    for g, w in zip(got, want):
        assert g == w and g.fit_report == w.fit_report
        assert g.control_points.tobytes() == w.control_points.tobytes()
    # The curves came back by pickle and evaluate as the local ones.
    t = np.linspace(0, 1, 101)
    assert all(same_bits(g(t), w(t)) for g, w in zip(got[:200], want[:200]))
