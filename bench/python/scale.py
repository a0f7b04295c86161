"""Scaling out: a batch of least-squares fits on 1 and 2 threads (fit_many) and on a Dask
LocalCluster of 1 and 2 worker processes (dask.bag over fit_many), best of --repeat.

    python bench/python/scale.py [--sets 20000] [--points 60] [--repeat 3]

Needs the package and dask[distributed]. Prints the seconds and the speed-ups 1 → 2; on a
machine shared with other work the speed-ups are only as good as the idle cores. The
results of every configuration are checked equal to the single-threaded ones. The point
sets are persisted on the workers first. Dask is timed twice: the fits with their results
kept on the workers (`persist`, as a pipeline that goes on working on them there), and the
fits with every fitted curve sent back to this process (`compute`: pickled on the workers,
unpickled here, one process doing all the unpickling).
"""

import argparse
import logging
import os
import time
import warnings

import numpy as np

import splinekit as sk


def best(repeat, run):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        result = run()
        times.append(time.perf_counter() - start)
    return min(times), result


def wait_for(collection):
    """The persisted collection once every partition of it is computed."""
    from dask.distributed import wait

    wait(collection)
    return collection


def fits(partition, run=0):
    """The fits of one partition; `run` only makes each timed run's task keys new, so Dask
    does not hand back results it still holds from an earlier run."""
    return sk.fit_many(partition, 3, 12, threads=1)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sets", type=int, default=20_000)
    parser.add_argument("--points", type=int, default=60)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    rng = np.random.default_rng(0)
    sets = [rng.normal(size=(args.points, 3)).cumsum(axis=0) for _ in range(args.sets)]
    print(f"{args.sets} fits of {args.points} points (cubic, 12 control points); {os.cpu_count()} CPUs, "
          f"load average {os.getloadavg()[0]:.1f}")

    reference = sk.fit_many(sets, 3, 12, threads=1)
    threads = {}
    for n in (1, 2):
        threads[n], got = best(args.repeat, lambda: sk.fit_many(sets, 3, 12, threads=n))
        assert got == reference
        print(f"fit_many, {n} thread{'s' if n > 1 else ''}: {threads[n]:.3f} s")
    print(f"fit_many speed-up 1 → 2 threads: {threads[1] / threads[2]:.2f}×")

    import dask.bag as db
    from dask.distributed import Client, LocalCluster

    workers, kept = {}, {}
    for n in (1, 2):
        with LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=None,
                          silence_logs=logging.ERROR) as cluster, Client(cluster):
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", UserWarning)  # "large graph": the point sets, once
                bag = db.from_sequence(sets, npartitions=8).persist()  # the data on the workers
            bag.map_partitions(fits).compute()  # warm the workers (imports, first pickles)
            runs = iter(range(1, 10**6))
            kept[n], on_workers = best(args.repeat, lambda: wait_for(bag.map_partitions(fits, next(runs)).persist()))
            assert on_workers.compute() == reference
            del on_workers
            workers[n], got = best(args.repeat, lambda: bag.map_partitions(fits, next(runs)).compute())
            assert got == reference
        label = f"Dask LocalCluster, {n} worker{'s' if n > 1 else ''}"
        print(f"{label}: {kept[n]:.3f} s with the results kept on the workers, {workers[n]:.3f} s sent back")
    print(f"Dask speed-up 1 → 2 workers: {kept[1] / kept[2]:.2f}× with the results kept on the workers, "
          f"{workers[1] / workers[2]:.2f}× with them sent back")


if __name__ == "__main__":
    main()
