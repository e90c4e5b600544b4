"""Evaluates one road over chunks of points in several processes: with `multiprocessing`
and with a Dask `LocalCluster`. The road is handed to the workers as it is: a `Road`
pickles (its file is read again in each worker, its checks and modifiers taken again).

usage: python examples/python_parallel.py ROAD [POINTS]   (Dask: pip install "dask[distributed]")
"""

import multiprocessing
import sys

import numpy as np

import opencrg


def elevations(road, u, v):
    """The work of one chunk, in a worker."""
    return road.uv_to_z(u, v)


def chunks(u, v, count):
    """The points in `count` chunks."""
    return list(zip(np.array_split(u, count), np.array_split(v, count)))


def with_multiprocessing(road, u, v, workers=2, count=8):
    """Elevations of every point, chunk by chunk in a pool of fresh processes."""
    with multiprocessing.get_context("spawn").Pool(workers) as pool:
        parts = pool.starmap(elevations, [(road, a, b) for a, b in chunks(u, v, count)])
    return np.concatenate(parts)


def with_dask(road, u, v, workers=2, count=8):
    """The same on a Dask cluster of local processes; the road is sent to each worker once."""
    from dask.distributed import Client, LocalCluster

    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with Client(cluster) as client:
            shared = client.scatter(road, broadcast=True)
            futures = [client.submit(elevations, shared, a, b) for a, b in chunks(u, v, count)]
            return np.concatenate(client.gather(futures))


def main():
    road = opencrg.Road(sys.argv[1])
    road.check()
    road.apply_modifiers()
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 1_000_000
    rng = np.random.default_rng(1)
    (u0, u1), (v0, v1) = road.u_range, road.v_range
    u, v = rng.uniform(u0, u1, n), rng.uniform(v0, v1, n)
    here = road.uv_to_z(u, v)
    pooled = with_multiprocessing(road, u, v)
    print(f"multiprocessing: {n} points, the same as in this process: {np.array_equal(pooled, here, equal_nan=True)}")
    try:
        dasked = with_dask(road, u, v)
    except ImportError:
        print("dask: not installed")
        return
    print(f"dask: {n} points, the same as in this process: {np.array_equal(dasked, here, equal_nan=True)}")


if __name__ == "__main__":
    main()
