"""Roads on the earth against PROJ: the chain from local x/y/z to WGS 84 for UTM,
Gauss-Krueger on Bessel without and with a Helmert transformation, and a user
transverse Mercator on a user ellipsoid, each within 1 mm of PROJ's explicit pipeline
and back within 0.1 mm; the global origin through modifiers."""

import math

import numpy as np
import pytest

import opencrg
from conftest import write_ldfi

pyproj = pytest.importorskip("pyproj", reason="pyproj (from PyPI) is installed by test.sh")

ARCSEC = 180.0 / math.pi * 3600.0
BESSEL = "+a=6377397.155 +rf=299.1528154"  # the DHDN variant of Bessel 1841
LDBV = dict(ds=-5.2379e-6, rx=0.7201 / ARCSEC, ry=0.1112 / ARCSEC, rz=-1.7209 / ARCSEC,
            tx=-604.7365, ty=-72.3946, tz=-424.402)


def helmert_keywords(t):
    return "".join(f"TRAN_{k.upper()} = {v!r}\n" for k, v in t.items())


# name: (map section, global origin east/north, PROJ pipeline from east/north/height)
CASES = {
    "utm": ("PROJ_NM = 'UTM_32U'\n", (691000.0, 5322000.0),
            "+step +inv +proj=utm +zone=32 +ellps=WGS84"),
    "utm_south": ("PROJ_NM = UTM_33H\n", (350000.0, 6250000.0),
                  "+step +inv +proj=utm +zone=33 +south +ellps=WGS84"),
    "gauss_krueger_nop": (
        "LELL_NM = BESSELDHDN\nPROJ_NM = GK3_4\n", (4478800.0, 5320500.0),
        f"+step +inv +proj=tmerc +lat_0=0 +lon_0=12 +k=1 +x_0=4500000 +y_0=0 {BESSEL} "
        f"+step +proj=cart {BESSEL} +step +inv +proj=cart +ellps=WGS84"),
    "gauss_krueger_hn7": (
        "LELL_NM = 'BESSELDHDN'\nTRAN_NM = 'HN7'\n" + helmert_keywords(LDBV) + "PROJ_NM = GK3_4\n",
        (4478800.0, 5320500.0),
        f"+step +inv +proj=tmerc +lat_0=0 +lon_0=12 +k=1 +x_0=4500000 +y_0=0 {BESSEL} "
        f"+step +proj=cart {BESSEL} "
        f"+step +inv +proj=helmert +x={LDBV['tx']!r} +y={LDBV['ty']!r} +z={LDBV['tz']!r} "
        f"+rx={LDBV['rx'] * ARCSEC!r} +ry={LDBV['ry'] * ARCSEC!r} +rz={LDBV['rz'] * ARCSEC!r} "
        f"+s={LDBV['ds'] * 1e6!r} +exact +convention=coordinate_frame "
        f"+step +inv +proj=cart +ellps=WGS84"),
    "user_tm": (
        "LELL_NM = USERDEFINED\nLELL_A = 6378000.0\nLELL_B = 6356500.0\nPROJ_NM = TM\nPROJ_F0 = 0.9999\n"
        "PROJ_P0 = 0.8\nPROJ_L0 = 0.2\nPROJ_E0 = 200000.0\nPROJ_N0 = -100000.0\n", (218000.0, 140000.0),
        "+step +inv +proj=tmerc +lat_0=45.83662361046586 +lon_0=11.459155902616464 +k=0.9999 "
        "+x_0=200000 +y_0=-100000 +a=6378000 +b=6356500 "
        "+step +proj=cart +a=6378000 +b=6356500 +step +inv +proj=cart +ellps=WGS84"),
}


def georeferenced(tmp_path, case, phi=0.35):
    section, (east, north), _ = CASES[case]
    header = (f"$ROAD_CRG\nREFERENCE_LINE_OFFSET_X = {east!r}\nREFERENCE_LINE_OFFSET_Y = {north!r}\n"
              f"REFERENCE_LINE_OFFSET_Z = 520.0\nREFERENCE_LINE_OFFSET_PHI = {phi!r}\n$\n"
              f"$ROAD_CRG_MPRO\n{section}$\n")
    return opencrg.Road(str(write_ldfi(tmp_path / f"{case}.crg", extra_header=header)))


def surface_points(road, n=200, seed=3):
    rng = np.random.default_rng(seed)
    (u0, u1), (v0, v1) = road.u_range, road.v_range
    u, v = rng.uniform(u0, u1, n), rng.uniform(v0, v1, n)
    x, y = road.uv_to_xy(u, v)
    z = np.nan_to_num(road.uv_to_z(u, v))
    return u, v, x, y, z


def metres(lat_a, lon_a, lat_b, lon_b):
    """The ground distance of two nearby positions in metres (north and east apart)."""
    north = np.radians(lat_a - lat_b) * 6_371_000.0
    east = np.radians(lon_a - lon_b) * 6_371_000.0 * np.cos(np.radians(lat_a))
    return np.hypot(north, east)


@pytest.mark.parametrize("case", sorted(CASES))
def test_wgs84_agrees_with_proj_within_a_millimetre(tmp_path, case):
    road = georeferenced(tmp_path, case)
    _, _, x, y, z = surface_points(road)
    lat, lon, alt = road.xyz_to_llh(x, y, z)
    e, n, h = road.xyz_to_enh(x, y, z)
    proj = pyproj.Transformer.from_pipeline(
        f"+proj=pipeline {CASES[case][2]} +step +proj=unitconvert +xy_in=rad +xy_out=deg")
    plon, plat, palt = proj.transform(e, n, h)
    assert np.max(metres(lat, lon, plat, plon)) < 1e-3
    assert np.max(np.abs(alt - palt)) < 1e-3
    # And back: local x/y/z within a tenth of a millimetre.
    bx, by, bz = road.llh_to_xyz(lat, lon, alt)
    assert np.max(np.hypot(bx - x, by - y)) < 1e-4
    assert np.max(np.abs(bz - z)) < 1e-4


def test_projected_frame_is_the_origin_turned_and_shifted(tmp_path):
    road = georeferenced(tmp_path, "utm", phi=0.35)
    x0, y0 = road.uv_to_xy(road.u_range[0], 0.0)  # the reference line's first point
    e, n, h = road.xyz_to_enh(x0 + 10.0, y0, 1.0)
    assert e == pytest.approx(691000.0 + x0 + 10.0 * math.cos(0.35), abs=1e-9)
    assert n == pytest.approx(5322000.0 + y0 + 10.0 * math.sin(0.35), abs=1e-9)
    assert h == pytest.approx(521.0)
    x, y, z = road.enh_to_xyz(e, n, h)
    assert (x, y, z) == pytest.approx((x0 + 10.0, y0, 1.0), abs=1e-9)


@pytest.mark.parametrize("modifiers", [
    {},  # the default relocation: the reference point to the origin, heading 0
    {"refpoint_x": 120.0, "refpoint_y": -35.0, "refpoint_z": 9.0},
    {"refpoint_u_fraction": 0.6, "refpoint_v_fraction": 0.3, "refpoint_phi": 2.2},
    {"refline_offset_phi": -1.3, "refline_offset_x": 4.0, "refline_offset_z": -2.5},
])
def test_the_surface_stays_in_place_in_wgs84_through_modifiers(tmp_path, modifiers):
    road = georeferenced(tmp_path, "gauss_krueger_hn7")
    u, v, x, y, z = surface_points(road, n=50)
    before = road.xyz_to_llh(x, y, z)
    origin = road.global_origin
    if modifiers:
        road.clear_modifiers()
        for name, value in modifiers.items():
            road.set_modifier(name, value)
    road.apply_modifiers()
    assert road.global_origin != origin
    x2, y2 = road.uv_to_xy(u, v)
    z2 = np.nan_to_num(road.uv_to_z(u, v))
    after = road.xyz_to_llh(x2, y2, z2)
    assert np.max(metres(before[0], before[1], after[0], after[1])) < 1e-4
    assert np.max(np.abs(before[2] - after[2])) < 1e-4


def test_setting_the_origin_pickles_and_roads_without_projection_refuse(tmp_path):
    import pickle
    road = georeferenced(tmp_path, "utm")
    road.global_origin = (1.0, 2.0, 3.0, 0.0)
    assert pickle.loads(pickle.dumps(road)).global_origin == (1.0, 2.0, 3.0, 0.0)
    with pytest.raises(ValueError):
        road.global_origin = (math.nan, 0.0, 0.0, 0.0)
    assert road.map_projection["projection"] == "UTM_32U"
    plain = opencrg.Road(str(write_ldfi(tmp_path / "plain.crg")))
    assert plain.map_projection is None
    with pytest.raises(ValueError, match="no map projection"):
        plain.xyz_to_llh(0.0, 0.0, 0.0)
    assert plain.xyz_to_enh(1.0, 2.0, 3.0) == (1.0, 2.0, 3.0)
