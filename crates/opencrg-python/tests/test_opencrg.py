"""The opencrg Python package against the Rust API (through the `opencrg` command), and
its own contract: shapes, NaN for refused points, options, modifiers, errors, data."""

import json
import subprocess
import threading

import numpy as np
import pytest

import opencrg
from conftest import same_bits, write_ldfi


def rust_eval(command, road_path, a, b, xy, raw):
    """Columns of `opencrg eval` (the Rust API, point by point on one contact point)."""
    points = "".join(f"{p!r} {q!r}\n" for p, q in zip(a.tolist(), b.tolist()))
    args = [command, "eval", str(road_path)] + (["--xy"] if xy else []) + (["--raw"] if raw else [])
    done = subprocess.run(args, input=points, capture_output=True, text=True, check=True)
    rows = [line.split(",") for line in done.stdout.splitlines()[1:]]
    return np.array([[float(x) for x in row] for row in rows]).T


def prepared(path, raw):
    road = opencrg.Road(path, compat="upstream")
    if not raw:
        road.check()
        road.apply_modifiers()
    return road


def random_uv(road, n, seed):
    rng = np.random.default_rng(seed)
    (u0, u1), (v0, v1) = road.u_range, road.v_range
    u = rng.uniform(u0 - 5.0, u1 + 5.0, n)
    v = rng.uniform(v0 - 1.0, v1 + 1.0, n)
    return u, v


@pytest.mark.parametrize("raw", [True, False])
def test_uv_calls_equal_the_rust_api_bit_for_bit(road_file, opencrg_command, raw):
    road = prepared(road_file, raw)
    u, v = random_uv(road, 3000, 1)
    u[:3], v[:3] = np.nan, 0.0  # refused points
    _, _, x, y, z, phi, curv = rust_eval(opencrg_command, road_file, u, v, xy=False, raw=raw)
    cp = opencrg.ContactPoint(road)
    assert same_bits(cp.uv_to_xy(u, v), (x, y))
    assert same_bits(cp.uv_to_z(u, v), z)
    assert same_bits(cp.uv_to_pk(u, v), (phi, curv))
    assert np.isnan(z[:3]).all()
    if not raw:  # NaN cells were filled by the default NaN modifier
        assert np.isfinite(z[3:]).all()


@pytest.mark.parametrize("raw", [True, False])
def test_xy_calls_equal_the_rust_api_bit_for_bit(road_file, opencrg_command, raw):
    road = prepared(road_file, raw)
    u, v = random_uv(road, 3000, 2)
    x, y = road.uv_to_xy(u, v)
    _, _, ru, rv, z, phi, curv = rust_eval(opencrg_command, road_file, x, y, xy=True, raw=raw)
    cp = opencrg.ContactPoint(road)
    assert same_bits(cp.xy_to_uv(x, y), (ru, rv))
    assert same_bits(cp.xy_to_z(x, y), z)
    assert same_bits(cp.xy_to_pk(x, y), (phi, curv))


@pytest.mark.parametrize("fmt", ["KDBI", "KRBI", "LDFI", "LRFI"])
def test_every_format_equals_the_rust_api(road_file, opencrg_command, tmp_path, fmt):
    written = tmp_path / f"road.{fmt}.crg"
    opencrg.Road(road_file).write(written, fmt)
    road = prepared(written, raw=False)
    assert road.format == fmt
    u, v = random_uv(road, 500, 3)
    _, _, x, y, z, _, _ = rust_eval(opencrg_command, written, u, v, xy=False, raw=False)
    assert same_bits(road.uv_to_z(u, v), z)
    assert same_bits(road.uv_to_xy(u, v), (x, y))


def test_scalars_arrays_and_broadcasting(road_file):
    road = opencrg.Road(road_file)
    u = np.linspace(1.0, 50.0, 12).reshape(3, 4)
    z = road.uv_to_z(u, 0.3)
    assert z.shape == (3, 4) and z.dtype == np.float64
    assert isinstance(road.uv_to_z(10.0, 0.3), float)
    assert road.uv_to_z(10.0, 0.3) == road.uv_to_z([10.0], [0.3])[0]
    assert same_bits(road.uv_to_z(u.tolist(), [0.3] * 4), z)
    assert same_bits([road.uv_to_z(a, 0.3) for a in u.ravel()], z.ravel())
    x, y = road.uv_to_xy(np.arange(5), 0)  # integers are read as float64
    assert x.shape == (5,) and y.shape == (5,)
    with pytest.raises(ValueError):
        road.uv_to_z(np.zeros(3), np.zeros(4))


def test_refused_points_are_nan(road_file):
    road = opencrg.Road(road_file)
    (u0, u1), (v0, v1) = road.u_range, road.v_range
    u = np.array([u0 - 1.0, 10.0, 10.0, u1 + 1.0, np.nan])
    v = np.array([0.0, v1 + 0.5, 0.0, 0.0, 0.0])
    z = road.uv_to_z(u, v, border_mode_u=opencrg.BORDER_NONE, border_mode_v=opencrg.BORDER_NONE)
    assert np.isnan(z[[0, 1, 3, 4]]).all() and np.isfinite(z[2])
    kept = road.uv_to_z(u, v)  # default border modes keep the last value
    assert np.isfinite(kept[:4]).all() and np.isnan(kept[4])


def test_a_contact_point_tells_which_points_it_refused(road_file):
    road = opencrg.Road(road_file)
    (u0, u1), (v0, v1) = road.u_range, road.v_range
    cp = opencrg.ContactPoint(road, border_mode_u=opencrg.BORDER_NONE, border_mode_v=opencrg.BORDER_NONE)
    assert cp.refused is False
    assert np.isnan(cp.uv_to_z(u0 - 1.0, 0.0)) and cp.refused is True
    assert np.isfinite(cp.uv_to_z(10.0, 0.0)) and cp.refused is False
    x, y = cp.uv_to_xy(10.0, v1 + 0.5)
    assert np.isfinite(x) and cp.refused is False
    assert np.isnan(cp.xy_to_z(x, y)) and cp.refused is True
    z = cp.uv_to_z(np.array([[u0 - 1.0, 10.0], [10.0, u1 + 1.0]]), np.zeros((2, 2)))
    assert cp.refused.dtype == bool and cp.refused.tolist() == np.isnan(z).tolist() == [[True, False], [False, True]]
    # A NaN cell's elevation is answered NaN, not refused (the C API's return code 1),
    # except with border mode none, where NaN at the border lies off the road.
    plain = opencrg.ContactPoint(road)
    assert np.isnan(plain.uv_to_z(1.0, 1.8)) and plain.refused is False
    assert np.isnan(cp.uv_to_z(1.0, 1.8)) and cp.refused is True
    assert road.closed_track is None and road.closed_track_report == (False, 0.0, 0.0)


def test_options_as_keywords_or_a_contact_point(road_file):
    road = opencrg.Road(road_file)
    u, v = random_uv(road, 400, 4)
    options = {"border_mode_u": opencrg.BORDER_REFLECT, "border_mode_v": opencrg.BORDER_REPEAT,
               "border_offset_v": 0.25, "border_smooth_ubeg": 2.0}
    cp = opencrg.ContactPoint(road, **options)
    assert cp.options["border_mode_v"] == opencrg.BORDER_REPEAT
    assert same_bits(cp.uv_to_z(u, v), road.uv_to_z(u, v, **options))
    assert not same_bits(cp.uv_to_z(u, v), road.uv_to_z(u, v))
    cp.set_option("border_mode_v", opencrg.BORDER_EX_ZERO)
    cp.remove_option("border_offset_v")
    assert "border_offset_v" not in cp.options
    cp.reset_options()
    assert cp.options["border_mode_v"] == opencrg.BORDER_EX_KEEP
    assert set(opencrg.OPTIONS) >= set(cp.options)
    with pytest.raises(KeyError, match="unknown option 'border_mode_w'"):
        road.uv_to_z(1.0, 0.0, border_mode_w=1)
    # The C API's message (its setter warns with it and keeps the value, as the reference).
    with pytest.raises(opencrg.OutOfRangeError, match="^<border mode u> = 9 is not one of its choices 0 to 4$"):
        opencrg.ContactPoint(road, border_mode_u=9)
    with pytest.raises(opencrg.OutOfRangeError, match="^<refline continuation mode> = -1 is not one"):
        cp.set_option("refline_continuation", -1)
    with pytest.raises(ValueError, match="greater than zero"):
        cp.set_option("border_smooth_uend", 0.0)
    with pytest.raises(TypeError):
        cp.set_option("border_mode_u", 1.5)


def test_history_gives_the_same_answers_as_single_calls(road_file):
    road = opencrg.Road(road_file)
    u, v = random_uv(road, 300, 5)
    x, y = road.uv_to_xy(u, v)
    batch = opencrg.ContactPoint(road, history=20)
    single = opencrg.ContactPoint(road, history=20)
    bu, bv = batch.xy_to_uv(x, y)
    pairs = [single.xy_to_uv(a, b) for a, b in zip(x, y)]
    assert same_bits((bu, bv), np.array(pairs).T)


def test_modifiers_apply_and_contact_points_follow(road_file, tmp_path):
    road = opencrg.Road(road_file)
    cp = opencrg.ContactPoint(road)
    before = cp.uv_to_xy(10.0, 0.5)
    assert road.modifiers["grid_nan_mode"] == opencrg.GRID_NAN_KEEP_LAST  # the defaults
    road.clear_modifiers()
    road.set_modifier("refline_offset_phi", 0.5)
    road.set_modifier("refline_offset_x", 3.0)
    assert road.modifiers["refline_offset_phi"] == 0.5
    road.apply_modifiers()
    after = cp.uv_to_xy(10.0, 0.5)
    assert after != before
    # The same modifiers given in the file's $ROAD_CRG_MODS section.
    mods = "$ROAD_CRG_MODS\nREFLINE_OFFSET_PHI = 0.5\nREFLINE_OFFSET_X = 3.0\n$\n"
    from_file = opencrg.Road(write_ldfi(tmp_path / "mods.crg", extra_header=mods))
    assert from_file.header["modifiers"] == {"refline_offset_phi": 0.5, "refline_offset_x": 3.0}
    from_file.apply_modifiers()
    u, v = random_uv(road, 200, 6)
    assert same_bits(road.uv_to_xy(u, v), from_file.uv_to_xy(u, v))
    road.remove_modifier("refline_offset_x")
    road.clear_modifiers()
    assert road.modifiers == {}
    with pytest.raises(KeyError):
        road.set_modifier("refline_offset_w", 1.0)


def test_data_arrays(road_file):
    road = opencrg.Road(road_file)
    g = road.grid
    assert g.dtype == np.float32 and g.shape == (241, 7)
    assert not g.flags.writeable
    with pytest.raises(ValueError):
        g[0, 0] = 1.0
    assert np.isnan(g[0, -1]) and np.isfinite(g[-1, -1])
    assert same_bits(road.v, [-2.0, -1.2, -0.5, 0.0, 0.4, 1.1, 2.0])
    line = road.reference_line
    assert line.u.shape == (241,) and same_bits(line.u, np.arange(241) * 0.25)
    assert line.x[0] == 10.0 and line.y[0] == -5.0
    assert np.allclose(line.phi, 0.3 + 0.01 * line.u)
    # The grid at the nodes, on a road without slope and banking, is what evaluation gives
    # there, less the reference line's elevation.
    flat = opencrg.Road(write_ldfi(road_file.parent / "flat.crg", slope=lambda u: 0.0, bank=lambda u: 0.0,
                                   nan_cells=lambda u, v: False))
    uu, vv = np.meshgrid(flat.reference_line.u, flat.v, indexing="ij")
    z = flat.uv_to_z(uu, vv)
    assert np.allclose(z, flat.grid.astype(np.float64) + flat.reference_line.z[:, None], atol=1e-6)


def test_header_sections(road_file):
    h = opencrg.Road(road_file).header
    assert h["comments"] == ["generated by the opencrg Python tests"]
    assert h["road_crg"]["REFERENCE_LINE_INCREMENT"] == 0.25
    assert h["format"] == "LDFI"
    assert h["channels"][:3] == ["reference line heading", "reference line slope", "reference line banking"]
    assert h["options"]["border_mode_u"] == opencrg.BORDER_EX_KEEP


def test_write_and_read_back(road_file, tmp_path):
    road = opencrg.Road(road_file)
    out = tmp_path / "copy.crg"
    road.write(out, "KDBI")
    back = opencrg.Road(out)
    assert same_bits(back.reference_line.x, road.reference_line.x)
    # The same surface. (The file read says nothing of the long sections' v range, so
    # its banking acts at v = 0 alone; the file written names the range, and its grid
    # carries the banking's share.)
    uu, vv = np.meshgrid(np.linspace(0.0, 60.0, 241), np.linspace(-2.0, 2.0, 9), indexing="ij")
    assert np.nanmax(np.abs(back.uv_to_z(uu, vv) - road.uv_to_z(uu, vv))) < 1e-7
    flat = opencrg.Road(write_ldfi(tmp_path / "unbanked.crg", bank=lambda u: 0.0))
    flat.write(out, "KDBI")
    assert same_bits(opencrg.Road(out).grid, flat.grid)
    # Format names in any case.
    for name in ("krbi", "Ldfi"):
        road.write(out, name)
        assert opencrg.Road(out).header["format"] == name.upper()
    with pytest.raises(ValueError, match="unknown format"):
        road.write(out, "XYZ")


def test_from_bytes_equals_from_file(road_file):
    a = opencrg.Road(road_file)
    b = opencrg.Road.from_bytes(road_file.read_bytes(), str(road_file))
    u, v = random_uv(a, 200, 7)
    assert same_bits(a.uv_to_z(u, v), b.uv_to_z(u, v))


def test_normals(road_file):
    road = opencrg.Road(road_file)
    u, v = random_uv(road, 500, 8)
    road.apply_modifiers()  # no NaN cells left
    z, nx, ny, nz = road.uv_to_normal(u, v)
    assert same_bits(z, road.uv_to_z(u, v))
    assert np.allclose(nx * nx + ny * ny + nz * nz, 1.0) and (nz > 0).all()
    # On the road, the x/y form answers as the u/v form at the same place.
    (u0, u1), (v0, v1) = road.u_range, road.v_range
    inside = (u > u0) & (u < u1) & (v > v0) & (v < v1)
    assert inside.sum() > 200
    x, y = road.uv_to_xy(u[inside], v[inside])
    by_xy = np.array(road.xy_to_normal(x, y))
    assert np.allclose(by_xy, np.array([z, nx, ny, nz])[:, inside], atol=1e-9)


def test_errors_name_the_file_line_and_field(tmp_path):
    missing = tmp_path / "missing.crg"
    with pytest.raises(FileNotFoundError) as e:
        opencrg.Road(missing)
    assert e.value.filename == str(missing) and "missing.crg" in str(e.value)
    bad = write_ldfi(tmp_path / "bad.crg")
    text = bad.read_text().replace("D:reference line slope,m/m", "D:reference line slope,furlong")
    bad.write_text(text)
    line = text.splitlines().index("D:reference line slope,furlong") + 1
    with pytest.raises(opencrg.FormatError) as e:
        opencrg.Road(bad)
    assert isinstance(e.value, ValueError) and isinstance(e.value, opencrg.CrgError)
    assert f"bad.crg:{line}: $KD_Definition" in str(e.value)
    with pytest.raises(opencrg.FormatError, match="is empty"):
        opencrg.Road.from_bytes(b"", "empty.crg")


def test_compat_profile(road_file, monkeypatch):
    u, v = random_uv(opencrg.Road(road_file), 300, 9)
    upstream = opencrg.Road(road_file, compat="upstream")
    release = opencrg.Road(road_file, compat="2.0.1")
    assert (upstream.compat, release.compat) == ("upstream", "2.0.1")
    assert not same_bits(upstream.uv_to_pk(u, v)[0], release.uv_to_pk(u, v)[0])
    monkeypatch.setenv("OPENCRG_COMPAT", "2.0.1")
    from_env = opencrg.Road(road_file)
    assert from_env.compat == "2.0.1"
    assert same_bits(from_env.uv_to_pk(u, v), release.uv_to_pk(u, v))
    monkeypatch.setenv("OPENCRG_COMPAT", "2.1-beta")
    with pytest.raises(ValueError, match="unknown compatibility profile '2.1-beta'"):
        opencrg.Road(road_file)


def test_threads_share_a_road(road_file):
    road = opencrg.Road(road_file)
    u, v = random_uv(road, 20000, 10)
    expected = road.uv_to_z(u, v)
    results = [None] * 4

    def work(k):
        results[k] = opencrg.ContactPoint(road).uv_to_z(u, v)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(same_bits(r, expected) for r in results)


def test_the_readme_example_runs(tmp_path, monkeypatch):
    from conftest import REPO

    text = (REPO / "README.md").read_text()
    code = text.split("```python\n", 1)[1].split("```", 1)[0]
    code = code.replace("examples/data/demo_road.crg", str(REPO / "examples/data/demo_road.crg"))
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "README.md", "exec"), {})
    assert opencrg.Road(tmp_path / "copy.crg").format == "KDBI"


def test_roughness_of_tracks_and_profiles(road_file, opencrg_command):
    road = opencrg.Road(road_file)
    tracks = road.roughness(segment=20.0)
    assert [t["v"] for t in tracks] == [-0.85, 0.0, 0.85]
    (u0, u1), (du, _) = road.u_range, road.increments
    u = u0 + du * np.arange(int(round((u1 - u0) / du)) + 1)
    for t in tracks:
        profile = road.uv_to_z(u, t["v"])
        assert t["iri"] == pytest.approx(opencrg.iri(profile, du), rel=1e-12)
        assert t["psd"]["gd_n0"] == pytest.approx(opencrg.psd(profile, du)["gd_n0"], rel=1e-12)
        assert t["psd"]["class"] in "ABCDEFGH"
        assert len(t["segments"]) == 3 and all(s["iri"] > 0 for s in t["segments"])
        total, parts = opencrg.iri(list(profile), du, segment=20.0)   # any array-like
        assert total == pytest.approx(t["iri"], rel=1e-12)
        assert parts == pytest.approx([s["iri"] for s in t["segments"]], rel=1e-12)
    # The command says the same (the road as read: this one has no checks or modifiers to apply).
    out = subprocess.run([opencrg_command, "roughness", str(road_file), "--segment", "20", "--json"],
                         check=True, capture_output=True, text=True).stdout
    for t, c in zip(tracks, json.loads(out)["tracks"]):
        assert c["iri"] == pytest.approx(t["iri"], rel=1e-12)
        assert c["psd"]["class"] == t["psd"]["class"]
    with pytest.raises(ValueError, match="outside"):
        road.roughness(tracks=[5.0])
    with pytest.raises(ValueError, match="too short"):
        opencrg.iri(np.zeros(20), 0.25)


def test_mesh_of_the_surface(road_file, opencrg_command, tmp_path):
    road = opencrg.Road(road_file)
    m = road.to_mesh(u=(5.0, 20.0))
    u, v = m["u"], m["v"]
    assert m["positions"].shape == (len(u) * len(v), 3) and m["triangles"].shape[1] == 3
    assert u[0] >= 5.0 and u[-1] <= 20.0 and list(v) == list(road.v)
    uu, vv = np.repeat(u, len(v)), np.tile(v, len(u))
    assert same_bits(m["positions"][:, 2], road.uv_to_z(uu, vv))
    x, y = road.uv_to_xy(uu, vv)
    assert same_bits(m["positions"][:, 0], x) and same_bits(m["positions"][:, 1], y)
    # Cells with a corner without elevation are left out, the others are all there.
    finite = np.isfinite(m["positions"][:, 2])
    assert finite[m["triangles"]].all()
    # The file the command writes holds the same mesh.
    road.write_mesh(tmp_path / "py.ply", u=(5.0, 20.0))
    subprocess.run([opencrg_command, "export", "--raw", str(road_file), str(tmp_path / "cli.ply"), "--u", "5:20"],
                   check=True, capture_output=True)
    assert (tmp_path / "py.ply").read_bytes() == (tmp_path / "cli.ply").read_bytes()
    # Simplified within 1 cm: fewer triangles, no grid, the same file as the command's.
    s = road.to_mesh(max_error=0.01)
    assert 0 < len(s["triangles"]) < len(road.to_mesh()["triangles"])
    assert len(s["u"]) == 0 and len(s["v"]) == 0 and np.isfinite(s["positions"]).all()
    road.write_mesh(tmp_path / "py_s.stl", max_error=0.01)
    subprocess.run([opencrg_command, "export", "--raw", str(road_file), str(tmp_path / "cli_s.stl"),
                    "--max-error", "0.01"], check=True, capture_output=True)
    assert (tmp_path / "py_s.stl").read_bytes() == (tmp_path / "cli_s.stl").read_bytes()
    with pytest.raises(ValueError, match="positive number"):
        road.to_mesh(max_error=-1.0)
    with pytest.raises(ValueError, match="unknown mesh format"):
        road.write_mesh(tmp_path / "x.gltf")


def test_every_evaluation_of_the_library_is_a_method_of_roads_and_contact_points(road_file):
    road = opencrg.Road(road_file)
    cp = opencrg.ContactPoint(road)
    assert len(opencrg.EVALUATIONS) == 8
    for name in opencrg.EVALUATIONS:
        assert callable(getattr(road, name)) and callable(getattr(cp, name)), name
    # xy_to_normal is uv_to_normal at the point's u/v.
    u, v = road.xy_to_uv([20.0, 55.5], [3.0, -1.0])
    assert same_bits(np.asarray(road.xy_to_normal([20.0, 55.5], [3.0, -1.0])), np.asarray(road.uv_to_normal(u, v)))
