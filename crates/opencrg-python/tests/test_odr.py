"""opencrg.odr: OpenDRIVE maps with CRG surfaces from Python: a shared map's roads found
again at their own points, a CRG record's height against its closed form, friction from
the lane material, pickling, refusals."""

import pathlib
import pickle

import numpy as np
import pytest

import opencrg
import opencrg.odr

SHARED = pathlib.Path(__file__).resolve().parents[4] / "shared" / "opendrive"

MAP = """<?xml version="1.0"?>
<OpenDRIVE><header revMajor="1" revMinor="8"/>
<road id="main" length="60" junction="-1">
<planView><geometry s="0" x="0" y="0" hdg="0" length="60"><line/></geometry></planView>
<elevationProfile><elevation s="0" a="1" b="0.01" c="0" d="0"/></elevationProfile>
<lanes><laneSection s="0">
<left><lane id="1" type="driving"><width sOffset="0" a="4" b="0" c="0" d="0"/><material sOffset="0" friction="0.8"/></lane></left>
<center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="4" b="0" c="0" d="0"/><material sOffset="0" friction="0.8"/></lane></right>
</laneSection></lanes>
<surface><CRG file="bumps.crg" sStart="10" sEnd="30" mode="attached" orientation="same" sOffset="10"/></surface>
</road></OpenDRIVE>"""


def test_points_of_a_town_find_their_road():
    town = opencrg.odr.Map(SHARED / "carla" / "Town01.xodr")
    ids = town.road_ids
    assert len(ids) == 98 and town.junctions == 12
    index = 5
    s = np.linspace(0.5, town.road_lengths[index] - 0.5, 50)
    x, y, z = town.st_to_xyz(ids[index], s, np.full_like(s, -1.5))
    g = town.ground(x, y)
    assert g["road"].shape == s.shape
    same = g["road"] == index
    assert same.mean() > 0.8
    assert np.allclose(g["s"][same], s[same], atol=1e-3) and np.allclose(g["t"][same], -1.5, atol=1e-3)
    assert np.allclose(g["z"], z, atol=1e-3)
    off = town.ground(1e6, 1e6)
    assert off["road"] == -1 and np.isnan(off["z"])
    assert town.check() == []


def test_crg_records_and_friction(tmp_path):
    a, b, c = 0.01, -0.02, 0.005
    line = np.column_stack([np.linspace(0.0, 20.0, 11), np.zeros(11)])
    bumps = opencrg.generate(line, 4.0, 0.25, 0.25, surface=lambda u, v: a * u + b * v + c)
    bumps.write(tmp_path / "bumps.crg")
    (tmp_path / "map.xodr").write_text(MAP)
    m = opencrg.odr.Map(tmp_path / "map.xodr")
    x = np.array([5.0, 15.0, 25.0, 40.0])
    y = np.array([1.0, -1.0, 1.5, 2.0])
    g = m.ground(x, y)
    own = 1.0 + 0.01 * x
    inside = (x >= 10) & (x <= 30)
    want = np.where(inside, own + a * (x - 10.0) + b * y + c, own)
    assert np.allclose(g["z"], want, atol=1e-4), (g["z"], want)
    assert np.all(g["friction"] == 0.8)
    assert list(g["lane"]) == [1, -1, 1, 1]
    n = m.normal(15.0, 0.0)
    assert abs(np.linalg.norm(n) - 1.0) < 1e-9 and n[2] > 0.99
    again = pickle.loads(pickle.dumps(m))
    assert np.array_equal(again.ground(x, y)["z"], g["z"])
    with pytest.raises(opencrg.RequestError, match="no road 'nope'"):
        m.st_to_xyz("nope", 1.0, 0.0)
    with pytest.raises(FileNotFoundError):
        opencrg.odr.Map(tmp_path / "missing.xodr")
    (tmp_path / "bad.xodr").write_text(MAP.replace('length="60"', 'length="sixty"'))
    with pytest.raises(opencrg.FormatError, match="bad.xodr:3"):
        opencrg.odr.Map(tmp_path / "bad.xodr")


DEMO_MAP = pathlib.Path(__file__).resolve().parents[3] / "examples" / "data" / "demo_map.xodr"


def test_the_mesh_lies_on_the_ground_and_is_written():
    m = opencrg.odr.Map(DEMO_MAP)
    mesh = m.to_mesh(max_error=0.005)
    p, tri = mesh["positions"], mesh["triangles"]
    assert p.shape[1] == 3 and tri.shape[1] == 3 and tri.dtype == np.uint32 and tri.max() < len(p)
    for name in ("friction", "road", "lane", "s", "t"):
        assert mesh[name].shape == (len(p),)
    # Each vertex on the ground odr's probes give at its x/y where the point finds the
    # vertex's own road and lane (at the joint of the two roads it may find the other
    # road; on a border between lanes, the outer lane, and the sidewalks stand 12 cm high).
    g = m.ground(p[:, 0], p[:, 1])
    own = (g["road"] == mesh["road"].astype(np.int64)) & (g["lane"] == mesh["lane"].astype(np.int64))
    assert own.mean() > 0.5
    assert np.nanmax(np.abs(g["z"][own] - p[own, 2])) < 1e-6
    # One group per lane of each road's section, none of type "none".
    assert len(mesh["groups"]) == 8
    assert {g["type"] for g in mesh["groups"]} == {"driving", "sidewalk"}
    assert sum(g["triangles"][1] - g["triangles"][0] for g in mesh["groups"]) == len(tri)
    # Friction per vertex from the lanes' materials: 0.9 on the first road, 0.7 on the other.
    driving = mesh["lane"] == 1
    assert {round(float(f), 3) for f in mesh["friction"][driving]} == {0.9, 0.7}
    only = m.to_mesh(max_error=0.005, roads=["2"], lanes=["driving"])
    assert set(only["road"]) == {1.0} and set(only["lane"]) == {-1.0, 1.0}


def test_the_mesh_is_written_and_refusals_raise(tmp_path):
    m = opencrg.odr.Map(DEMO_MAP)
    out = tmp_path / "map.glb"
    m.write_mesh(out, max_error=0.005)
    assert out.read_bytes()[:4] == b"glTF"
    with pytest.raises(opencrg.RequestError, match="no road 'x'"):
        m.to_mesh(roads=["x"])
    with pytest.raises(opencrg.RequestError):
        m.to_mesh(max_error=-1.0)
    with pytest.raises(opencrg.RequestError):
        m.to_mesh(max_memory=1000)
    with pytest.raises(opencrg.RequestError):
        m.write_mesh(tmp_path / "map.xyz")
    assert not (tmp_path / "map.xyz").exists()
