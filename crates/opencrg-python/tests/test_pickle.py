"""Roads and contact points pickle: unpickled, they give the same answers bit for bit,
their checks, modifiers, profile, options and search history included; and one road
evaluated over chunks of points in other processes (multiprocessing, Dask) gives the
answers it gives here."""

import os
import pickle
import sys

import numpy as np
import pytest

import opencrg
from conftest import REPO, same_bits, write_krbi

sys.path.insert(0, str(REPO / "examples"))
import python_parallel  # noqa: E402


def points(road, n=2000, seed=3):
    rng = np.random.default_rng(seed)
    (u0, u1), (v0, v1) = road.u_range, road.v_range
    return rng.uniform(u0 - 2.0, u1 + 2.0, n), rng.uniform(v0 - 0.5, v1 + 0.5, n)


def same_answers(a, b):
    u, v = points(a)
    x, y = a.uv_to_xy(u, v)
    for name, p, q in [("uv_to_z", u, v), ("uv_to_xy", u, v), ("uv_to_pk", u, v), ("xy_to_uv", x, y),
                       ("xy_to_z", x, y), ("uv_to_normal", u, v)]:
        assert same_bits(getattr(a, name)(p, q), getattr(b, name)(p, q)), name


def again(thing):
    return pickle.loads(pickle.dumps(thing))


def test_a_road_from_a_file_pickles_with_its_changes(road_file):
    road = opencrg.Road(road_file, compat="2.0.1")
    same_answers(road, again(road))
    road.check()
    road.set_modifier("refline_offset_phi", 0.4)
    road.set_modifier("grid_nan_mode", opencrg.GRID_NAN_SET_ZERO)
    road.remove_modifier("grid_nan_offset")
    road.apply_modifiers()
    copy = again(road)
    same_answers(road, copy)
    assert copy.modifiers == road.modifiers
    assert same_bits(copy.grid, road.grid)
    # The profile travels too: the same road read by the other profile answers otherwise.
    other = opencrg.Road(road_file, compat="upstream")
    other.check()
    other.set_modifier("refline_offset_phi", 0.4)
    other.set_modifier("grid_nan_mode", opencrg.GRID_NAN_SET_ZERO)
    other.apply_modifiers()
    u, v = points(road)
    assert not same_bits(other.uv_to_xy(u, v), copy.uv_to_xy(u, v))


def test_a_road_from_bytes_pickles_its_bytes(road_file, tmp_path):
    road = opencrg.Road.from_bytes(road_file.read_bytes(), "in memory")
    road.clear_modifiers()
    road.apply_modifiers()
    data = pickle.dumps(road)
    road_file.unlink()
    same_answers(road, pickle.loads(data))


def test_a_changed_or_missing_file_is_refused(road_file):
    data = pickle.dumps(opencrg.Road(road_file))
    with open(road_file, "a") as f:
        f.write("\n")
    with pytest.raises(ValueError, match="changed since the road was pickled"):
        pickle.loads(data)
    road_file.unlink()
    with pytest.raises(FileNotFoundError):
        pickle.loads(data)


def test_a_contact_point_pickles_with_its_road_options_and_history(road_file):
    road = opencrg.Road(road_file)
    road.apply_modifiers()
    cp = opencrg.ContactPoint(road, history=7, border_mode_u=opencrg.BORDER_REPEAT, refline_search_far=0.7)
    cp.remove_option("border_mode_v")
    u, v = points(road, 300, 5)
    x, y = road.uv_to_xy(u, v)
    cp.xy_to_uv(x[:150], y[:150])  # a search history to carry
    copy = again(cp)
    assert copy.options == cp.options
    # The same next searches (they start from the history) and the same elevations.
    assert same_bits(copy.xy_to_uv(x[150:], y[150:]), cp.xy_to_uv(x[150:], y[150:]))
    assert same_bits(copy.uv_to_z(u, v), cp.uv_to_z(u, v))
    # Several contact points on one road carry that road once.
    a, b = again([cp, opencrg.ContactPoint(road)])
    assert a.road is b.road


def test_inputs_need_not_be_contiguous_or_aligned(road_file):
    road = opencrg.Road(road_file)
    u, v = points(road, 101, 4)
    # Every other point, and the points in a byte buffer one byte off (as arrays arrive
    # from other processes).
    buffer = bytearray(u.nbytes + 1)
    shifted = np.frombuffer(buffer, dtype=np.float64, count=u.size, offset=1)
    assert not shifted.flags.aligned
    np.copyto(shifted, u)
    assert same_bits(road.uv_to_z(shifted, v), road.uv_to_z(u, v))
    assert same_bits(road.uv_to_z(u[::2], v[::2]), road.uv_to_z(u, v)[::2])


def test_one_road_over_chunks_with_multiprocessing(road_file):
    road = opencrg.Road(road_file)
    road.check()
    road.apply_modifiers()
    u, v = points(road, 20_000, 8)
    assert same_bits(python_parallel.with_multiprocessing(road, u, v), road.uv_to_z(u, v))


def test_one_road_over_chunks_with_dask(road_file):
    if os.environ.get("OPENCRG_TEST_DASK") == "0":
        pytest.skip("OPENCRG_TEST_DASK=0")
    road = opencrg.Road(road_file)
    road.check()
    road.apply_modifiers()
    u, v = points(road, 20_000, 9)
    assert same_bits(python_parallel.with_dask(road, u, v), road.uv_to_z(u, v))


def test_a_road_read_in_place_pickles_as_its_file_not_its_grid(tmp_path):
    path = write_krbi(tmp_path / "long.crg", n_u=20_001, n_v=401)
    road = opencrg.Road(path, in_place=True)
    assert road.in_place and not opencrg.Road(path, in_place=False).in_place
    road.check()
    road.apply_modifiers()
    data = pickle.dumps(road)
    assert len(data) < 2_000 < path.stat().st_size // 10_000
    copy = pickle.loads(data)
    assert copy.in_place
    same_answers(road, copy)
    memory = opencrg.Road(path, in_place=False)
    memory.check()
    memory.apply_modifiers()
    same_answers(road, memory)
    # A road read into memory is unpickled into memory, whatever the worker's environment.
    assert not again(opencrg.Road(path, in_place="1T")).in_place
    with pytest.raises(opencrg.RequestError, match="in_place"):
        opencrg.Road(path, in_place="sometimes")


def test_parts_of_one_big_road_read_in_place_by_dask_workers(tmp_path):
    """A road of 0.8 GB read in place here and by the workers of a Dask LocalCluster of
    worker processes, each evaluating parts of it: the answers of this process, bit for
    bit, and each worker holding less private memory than a fifth of the road (its Python,
    Dask and the reference line; the grid is the file's, in the system's cache)."""
    if os.environ.get("OPENCRG_TEST_DASK") == "0":
        pytest.skip("OPENCRG_TEST_DASK=0")
    from dask.distributed import Client, LocalCluster

    path = write_krbi(tmp_path / "big.crg", n_u=200_001, n_v=1001)
    road = opencrg.Road(path, in_place=True, cache="16M")
    road.check()
    road.apply_modifiers()
    u, v = points(road, 40_000, 10)
    here = road.uv_to_z(u, v)
    x, y = road.uv_to_xy(u, v)
    with LocalCluster(n_workers=3, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with Client(cluster) as client:
            shared = client.scatter(road, broadcast=True)
            parts = python_parallel.chunks(u, v, 12)
            futures = [client.submit(python_parallel.elevations, shared, a, b) for a, b in parts]
            searched = [client.submit(_xy_to_z, shared, a, b) for a, b in python_parallel.chunks(x, y, 12)]
            assert same_bits(np.concatenate(client.gather(futures)), here)
            assert same_bits(np.concatenate(client.gather(searched)), road.xy_to_z(x, y))
            private = client.run(_private_kib)
    assert len(private) == 3
    assert all(kib * 1024 < path.stat().st_size / 5 for kib in private.values()), private


def _xy_to_z(road, x, y):
    """x/y to z in a worker (each worker's own contact point: the road's batch call)."""
    return road.xy_to_z(x, y)


def _private_kib():
    """This process's private memory (RssAnon) in KiB."""
    with open("/proc/self/status") as f:
        return next(int(line.split()[1]) for line in f if line.startswith("RssAnon:"))
