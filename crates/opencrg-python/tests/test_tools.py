"""The road tools from Python: the same roads as the `opencrg` command makes, surfaces
kept where they were, pickling of made roads."""

import math
import pickle
import platform
import subprocess

import numpy as np
import pytest

import opencrg


def sine_line(path=None):
    x = np.arange(0.0, 121.0, 2.0)
    pts = np.column_stack([x, 10.0 * np.sin(x / 25.0), 0.02 * x])
    if path is not None:
        np.savetxt(path, pts, delimiter=",", header="x,y,z", comments="")
    return pts


def run(cmd, *args):
    out = subprocess.run([cmd, *map(str, args)], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return out.stdout


def same_road(a, b):
    """Equal grids (NaN equal), long sections, reference lines."""
    ga, gb = np.asarray(a.grid), np.asarray(b.grid)
    assert ga.shape == gb.shape
    assert np.array_equal(ga, gb, equal_nan=True)
    assert np.array_equal(a.v, b.v)
    la, lb = a.reference_line, b.reference_line
    assert np.allclose(la.x, lb.x, rtol=0, atol=1e-9) and np.allclose(la.y, lb.y, rtol=0, atol=1e-9)


def test_python_makes_the_roads_the_command_makes(tmp_path, road_file, opencrg_command):
    line = tmp_path / "line.csv"
    pts = sine_line(line)
    cmd_road = tmp_path / "gen.crg"
    run(opencrg_command, "generate", cmd_road, "--refline", line, "--width", 4, "--u-inc", 0.1, "--v-inc", 0.25)
    py_road = opencrg.generate(pts, 4.0, 0.1, 0.25)
    same_road(opencrg.Road(cmd_road), py_road)
    assert np.array_equal(opencrg.read_points(line), pts)

    road = opencrg.Road(road_file)
    cases = {
        "cut": (["cut", "--u", "10:40", "--v", "-1:1.5"], lambda r: r.cut((10.0, 40.0), (-1.0, 1.5))),
        "flip": (["flip"], lambda r: r.flip()),
        "resample": (["resample", "--u-inc", "0.4", "--v-inc", "0.3"], lambda r: r.resample(0.4, 0.3)),
        "gauss": (["filter", "--gauss", "0.3"], lambda r: r.filter(gauss=0.3)),
        "median": (["filter", "--median", "3"], lambda r: r.filter(median=3)),
        "fill": (["filter", "--fill-nan"], lambda r: r.filter(fill_nan=True)),
        "slope": (["slope", "--apply"], lambda r: r.slope("apply")),
        "banking": (["banking", "--extract"], lambda r: r.banking("extract")),
    }
    for name, (args, method) in cases.items():
        out = tmp_path / f"{name}.crg"
        run(opencrg_command, args[0], road_file, out, *args[1:], "--format", "KDBI")
        same_road(opencrg.Road(out), method(road))


def test_made_roads_keep_the_surface_and_pickle(road_file):
    road = opencrg.Road(road_file)
    first, second = road.cut((0.0, 25.0)), road.cut((25.0, 60.0))
    joined = first.append(second)
    c = opencrg.compare(road, joined)
    assert c["max_difference"] < 1e-4 and c["compared"] > 1000
    flipped = road.flip()
    assert opencrg.compare(road, flipped)["max_difference"] < 1e-4
    back = pickle.loads(pickle.dumps(flipped))
    same_road(back, flipped)
    u = np.linspace(1.0, 50.0, 200)
    assert np.array_equal(back.uv_to_z(u, 0.3), flipped.uv_to_z(u, 0.3), equal_nan=True)
    with pytest.raises(ValueError, match="fewer than two"):
        road.cut((500.0, 600.0))
    with pytest.raises(ValueError, match="exactly one"):
        road.filter(gauss=0.1, median=3)


def test_generate_takes_a_surface_function_or_a_road():
    pts = sine_line()
    road = opencrg.generate(pts[:, :2], 4.0, 0.2, 0.5, surface=lambda u, v: 0.01 * np.sin(u) + 0.02 * v)
    g = np.asarray(road.grid)
    u = road.u_range[0] + 0.2 * np.arange(g.shape[0])
    assert np.allclose(g[:, 0], 0.01 * np.sin(u) - 0.04, atol=1e-6)
    again = opencrg.generate(pts[:, :2], 4.0, 0.2, 0.5, surface=road)
    assert np.allclose(np.asarray(again.grid), g, atol=1e-6)


def test_a_cloud_sampled_from_a_surface_comes_back():
    rng = np.random.default_rng(5)
    n = 120_000
    x = rng.uniform(0.0, 60.0, n)
    y = rng.uniform(-4.0, 4.0, n)
    z = 3.0 + 0.05 * np.sin(x / 3.0) + 0.02 * np.cos(y)
    line = np.array([[2.0, 0.0], [30.0, 0.5], [58.0, 0.0]])
    road = opencrg.import_points(np.column_stack([x, y, z]), 0.25, 0.25, refline=line, width=6.0)
    g = np.asarray(road.grid)
    assert np.isnan(g).mean() < 0.01
    uu, vv = np.meshgrid(road.u_range[0] + 0.25 * np.arange(g.shape[0]), road.v, indexing="ij")
    xs, ys = road.uv_to_xy(uu, vv)
    zs = road.uv_to_z(uu, vv)
    want = 3.0 + 0.05 * np.sin(xs / 3.0) + 0.02 * np.cos(ys)
    ok = ~np.isnan(zs)
    assert np.max(np.abs(zs[ok] - want[ok])) < 0.002


def test_a_cloud_with_stray_points_is_imported_cropped():
    rng = np.random.default_rng(6)
    n = 20_000
    x, y = rng.uniform(0.0, 60.0, n), rng.uniform(-4.0, 4.0, n)
    points = np.column_stack([x, y, 0.01 * np.sin(x)])
    stray = np.vstack([points, [[6.0e6, 0.0, 0.0], [30.0, -6.0e6, 0.0]]])
    with pytest.raises(opencrg.RequestError) as e:
        opencrg.import_points(stray, 1.0, 1.0)
    assert "stray points?" in str(e.value)
    road = opencrg.import_points(stray, 1.0, 1.0, crop=((-10.0, 70.0), (-10.0, 10.0)))
    plain = opencrg.import_points(points, 1.0, 1.0)
    assert np.asarray(road.grid).shape == np.asarray(plain.grid).shape


def test_write_fmu_packs_what_the_command_packs(tmp_path, road_file, opencrg_command):
    import zipfile

    report = opencrg.write_fmu(road_file, tmp_path / "py.fmu", wheels=2, fmi=3)
    assert report["identifier"] == "curved" and report["variables"] == 1 + 11 + 2 * 13, report
    machine = platform.machine().lower()
    here = {"amd64": "x86_64", "arm64": "aarch64"}.get(machine, machine) + "-" + platform.system().lower()
    assert here in report["platforms"], report
    run(opencrg_command, "fmu", road_file, tmp_path / "cli.fmu", "--wheels", 2, "--fmi", 3)
    with zipfile.ZipFile(tmp_path / "py.fmu") as py, zipfile.ZipFile(tmp_path / "cli.fmu") as cli:
        names = [n for n in py.namelist() if not n.startswith("binaries/")]
        assert names == [n for n in cli.namelist() if not n.startswith("binaries/")]
        for name in names:
            assert py.read(name) == cli.read(name), name
        assert f"binaries/{here}/curved.so" in py.namelist()
    with pytest.raises(opencrg.RequestError, match="fmi=4"):
        opencrg.write_fmu(road_file, tmp_path / "bad.fmu", fmi=4)
    with pytest.raises(opencrg.RequestError, match="no FMU binary"):
        opencrg.write_fmu(road_file, tmp_path / "bad.fmu", binaries=tmp_path)
    assert not (tmp_path / "bad.fmu").exists()
