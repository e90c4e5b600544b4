"""FMUs of `opencrg fmu` driven by FMPy as a user drives them.

A CRG file and shared OpenDRIVE maps carrying CRG records of this test's own (every
mode and orientation, elevation and friction) are packed as FMUs, FMI 2.0 and 3.0; FMPy
validates each and simulates it in co-simulation and model exchange, four wheels driven
along the road by an input table. Every output row is compared, to the bit, with what
the C API answers at the x/y the FMU held (ctypes on libopencrg: crgEvalxy2uv,
crgEvalxy2z, crgEvaluv2pk for a CRG file; crgOdrEvalxy and crgOdrEvalxy2normal for a
map) and, for a map, with `opencrg odr eval`. Also: a get after a set answers at once;
two instances of different roads on two threads; an FMU unpacked into a folder whose
name has a space and a non-ASCII letter; calls in the wrong state and unknown value
references refused with a message; NaN positions off the road; an FMU whose CRG file
is missing refused at instantiation, naming the file, the process going on.

Needs: OPENCRG_CLI (the opencrg command, release build, with the FMU binary beside it),
OPENCRG_LIB (libopencrg.so), ../shared beside the checkout; pip packages fmpy, numpy.
"""

import ctypes
import math
import os
import pathlib
import shutil
import subprocess
import threading
import zipfile

import fmpy
import numpy as np
import pytest
from fmpy.fmi2 import FMU2Model, FMU2Slave, fmi2CallbackFunctions, fmi2CallbackLoggerTYPE
from fmpy.fmi3 import FMU3Model, FMU3Slave
from fmpy.validation import validate_fmu

ROOT = pathlib.Path(__file__).resolve().parents[4]
SHARED = ROOT.parent / "shared"
CLI = os.environ.get("OPENCRG_CLI", str(ROOT / "target/release/opencrg"))
LIB = os.environ.get("OPENCRG_LIB", str(ROOT / "target/release/libopencrg.so"))
# Input times on a dyadic grid, so that FMPy's interpolation of the table hands the FMU
# the table's values exactly.
DT = 2.0**-7
WHEELS = 4


def cli(*args, stdin=None):
    done = subprocess.run([CLI, *map(str, args)], input=stdin, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout


# --- the C API, as a C program calls it --------------------------------------------------

capi = ctypes.CDLL(LIB)
capi.crgMsgSetLevel(0)
D = ctypes.c_double
P = ctypes.POINTER
capi.crgEvalxy2uv.argtypes = [ctypes.c_int, D, D, P(D), P(D)]
capi.crgEvalxy2z.argtypes = [ctypes.c_int, D, D, P(D)]
capi.crgEvaluv2pk.argtypes = [ctypes.c_int, D, D, P(D), P(D)]
capi.crgOdrEvalxy.argtypes = [ctypes.c_int, D, D, P(D), P(D), P(ctypes.c_int), P(ctypes.c_int), P(D), P(D)]
capi.crgOdrEvalxy2normal.argtypes = [ctypes.c_int, D, D, P(D), P(D), P(D)]
capi.crgOdrEvalst2xyz.argtypes = [ctypes.c_int, ctypes.c_int, D, D, P(D), P(D), P(D)]


def road_xy(path):
    """A function of (s, t) giving the x/y of the CRG file's u = (s - 90) * 0.3, v = t (through
    the C API's u/v to x/y after the modifiers): s 87 to 170 runs over u -1 to 23."""
    data = capi.crgLoaderReadFile(str(path).encode())
    capi.crgDataSetModifiersApply(data)
    cp = capi.crgContactPointCreate(data)
    capi.crgEvaluv2xy.argtypes = [ctypes.c_int, D, D, P(D), P(D)]
    x, y = D(), D()

    def xy_of(s, t):
        capi.crgEvaluv2xy(cp, (s - 90.0) * 0.3, t, ctypes.byref(x), ctypes.byref(y))
        return x.value, y.value

    return xy_of


def crg_oracle(path):
    """A function of (x, y) giving the CRG file's answers as the FMU documents them: u and v
    of a contact point asked only crgEvalxy2uv at the wheel's positions in turn, z of one
    asked only crgEvalxy2z (a search starts where the contact point's last one ended, so
    that a second search at the same x/y may end a bit away from the first)."""
    data = capi.crgLoaderReadFile(str(path).encode())
    assert data > 0 and capi.crgCheck(data) == 1
    capi.crgDataSetModifiersApply(data)
    cp, z_cp = capi.crgContactPointCreate(data), capi.crgContactPointCreate(data)
    u, v, z, phi, curv = D(), D(), D(), D(), D()

    def answer(x, y):
        found = capi.crgEvalxy2uv(cp, x, y, ctypes.byref(u), ctypes.byref(v)) == 1
        height = capi.crgEvalxy2z(z_cp, x, y, ctypes.byref(z)) == 1 and math.isfinite(z.value)
        pk = found and capi.crgEvaluv2pk(cp, u.value, v.value, ctypes.byref(phi), ctypes.byref(curv)) == 1
        return {
            "u": u.value if found else 0.0,
            "v": v.value if found else 0.0,
            "z": z.value if height else 0.0,
            "heading": phi.value if pk else 0.0,
            "curvature": curv.value if pk else 0.0,
        }

    return answer


def map_oracle(path, friction_default):
    """A function of (x, y) giving the answers the FMU documents for one wheel: what a
    probe of its own answers at each new position, the normal from a second one."""
    the_map = capi.crgOdrMapLoad(str(path).encode())
    probe, normal_probe = capi.crgOdrProbeCreate(the_map), capi.crgOdrProbeCreate(the_map)
    assert probe >= 0 and normal_probe >= 0
    z, mu, s, t, nx, ny, nz = D(), D(), D(), D(), D(), D(), D()
    road, lane = ctypes.c_int(), ctypes.c_int()
    last = {}

    def answer(x, y):
        if last.get("at") != (x, y):
            last["at"], last["answer"] = (x, y), fresh(x, y)
        return last["answer"]

    def fresh(x, y):
        on = capi.crgOdrEvalxy(probe, x, y, *map(ctypes.byref, (z, mu, road, lane, s, t))) == 1
        on = on and math.isfinite(z.value)
        if not on:
            return {"onRoad": False, "z": 0.0, "friction": friction_default, "s": 0.0, "t": 0.0, "road": -1,
                    "lane": 0, "nx": 0.0, "ny": 0.0, "nz": 1.0}
        normal = capi.crgOdrEvalxy2normal(normal_probe, x, y, *map(ctypes.byref, (nx, ny, nz))) == 1
        return {
            "onRoad": True, "z": z.value, "s": s.value, "t": t.value, "road": road.value, "lane": lane.value,
            "friction": mu.value if math.isfinite(mu.value) else friction_default,
            "nx": nx.value if normal else 0.0, "ny": ny.value if normal else 0.0, "nz": nz.value if normal else 1.0,
        }

    return answer


def road_points(path, road, s, t):
    """World x/y of (s, t) on the road with index `road`."""
    probe = capi.crgOdrProbeCreate(capi.crgOdrMapLoad(str(path).encode()))
    x, y, z = D(), D(), D()
    out = []
    for si, ti in zip(s, t):
        assert capi.crgOdrEvalst2xyz(probe, road, si, ti, ctypes.byref(x), ctypes.byref(y), ctypes.byref(z)) == 1
        out.append((x.value, y.value))
    return out


# --- the roads ---------------------------------------------------------------------------

def line_csv(path, x0, y0, heading, length, bend=0.0, climb=0.0):
    """A reference line's points: from (x0, y0) at `heading`, turning by `bend` per metre."""
    rows, x, y, h = ["x,y,z"], x0, y0, heading
    for k in range(int(length) + 1):
        rows.append(f"{x!r},{y!r},{climb * k!r}")
        x, y, h = x + math.cos(h), y + math.sin(h), h + bend
    path.write_text("\n".join(rows) + "\n")
    return path


@pytest.fixture(scope="module")
def work(tmp_path_factory):
    d = tmp_path_factory.mktemp("fmu")
    cli("generate", d / "rough.crg", "--refline", line_csv(d / "rough.csv", 230.0, 150.0, 1.2, 60, 0.004, 0.02),
        "--width", 6, "--u-inc", 0.1, "--v-inc", 0.1,
        "--surface", "0.004*sin(u*3.1)*cos(v*1.7)+0.002*cos(u*11)")
    cli("generate", d / "flat.crg", "--refline", line_csv(d / "flat.csv", -40.0, 25.0, 0.3, 60),
        "--width", 6, "--u-inc", 0.1, "--v-inc", 0.1, "--surface", "0.005*sin(u*2.3)+0.003*cos(v*5)")
    cli("generate", d / "grip.crg", "--refline", line_csv(d / "grip.csv", 0.0, 0.0, 0.0, 40),
        "--width", 8, "--u-inc", 0.5, "--v-inc", 0.5, "--surface", "0.7+0.1*sin(u)*cos(v)")
    return d


# The records: each elevation mode and orientation, with a friction record, on the road of
# esmini's curves_elevation.xodr between s 100 and 160 (where the global record's CRG lies).
FRICTION = '<CRG file="grip.crg" sStart="105" sEnd="150" purpose="friction" mode="attached" sOffset="105"/>'
MODES = {
    "attached": '<CRG file="flat.crg" sStart="100" sEnd="160" purpose="elevation" mode="attached" '
                'orientation="same" sOffset="100" tOffset="0.25"/>',
    "attached_opposite": '<CRG file="flat.crg" sStart="100" sEnd="160" purpose="elevation" mode="attached" '
                         'orientation="opposite" sOffset="160" tOffset="-0.5"/>',
    "attached0": '<CRG file="rough.crg" sStart="100" sEnd="160" purpose="elevation" mode="attached0" '
                 'orientation="same" sOffset="100" zScale="0.5" zOffset="0.2"/>',
    "genuine": '<CRG file="rough.crg" sStart="100" sEnd="160" purpose="elevation" mode="genuine" '
               'sOffset="100" tOffset="0.5" hOffset="0.05"/>',
    "global": '<CRG file="flat.crg" sStart="100" sEnd="160" purpose="elevation" mode="global" '
              'xOffset="140" yOffset="-25" hOffset="-0.2" zScale="2"/>',
}


def map_with(work, name, records):
    text = (SHARED / "opendrive/esmini/curves_elevation.xodr").read_text()
    at = text.rfind("</road>")
    path = work / f"{name}.xodr"
    path.write_text(text[:at] + f"<surface>{records}</surface>\n" + text[at:])
    return path


def pack(road, out, fmi, wheels=WHEELS):
    cli("fmu", road, out, "--fmi", fmi, "--wheels", wheels)
    return out


def wheel_path(xy_of, n=160):
    """Four wheels (front left/right, rear left/right) along s 90 to 170, weaving a little."""
    s = 90.0 + np.arange(n) * 0.5
    rows = []
    for k in range(n):
        row = [k * DT]
        for ds, t in ((0.0, 0.8), (0.0, -0.8), (-2.7, 0.8), (-2.7, -0.8)):
            row.extend(xy_of(s[k] + ds, t + 0.6 * math.sin(0.15 * k)))
        rows.append(tuple(row))
    names = [("time", np.float64)]
    for i in range(1, WHEELS + 1):
        names += [(f"wheel[{i}].x", np.float64), (f"wheel[{i}].y", np.float64)]
    return np.array(rows, dtype=names)


def simulate(fmu, fmi_type, table, outputs, start_values=None):
    """The FMU along the table; model exchange with fixed steps at the table's times, so
    that a map's wheel meets the positions the oracle replays (a variable-step solver
    reads the event indicators at positions between them too, and a map's wheel answers
    as a probe meeting each position set in turn)."""
    stop = float(table["time"][-1])
    solver = "Euler" if fmi_type == "ModelExchange" else None
    return fmpy.simulate_fmu(fmu, fmi_type=fmi_type, input=table, output=outputs, step_size=DT, solver=solver,
                             output_interval=DT, stop_time=stop, start_values=start_values or {})


def instantiated(md, unzipped, fmi, said):
    """A co-simulation instance of FMI `fmi` whose messages are appended to `said`
    (instantiation's refusal raised)."""
    if fmi == 2:
        callbacks = fmi2CallbackFunctions()
        callbacks.logger = fmi2CallbackLoggerTYPE(lambda env, name, status, cat, msg: said.append(msg.decode()))
        slave = FMU2Slave(guid=md.guid, unzipDirectory=unzipped, modelIdentifier=md.coSimulation.modelIdentifier)
        slave.instantiate(callbacks=callbacks)
    else:
        slave = FMU3Slave(guid=md.guid, unzipDirectory=unzipped, modelIdentifier=md.coSimulation.modelIdentifier)
        slave.instantiate(logMessage=lambda env, status, cat, msg: said.append(msg.decode()))
    return slave


def same(a, b):
    return (isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b)) or a == b


# --- the tests ---------------------------------------------------------------------------

@pytest.mark.parametrize("fmi", [2, 3])
def test_crg_file_answers_as_the_c_api(work, fmi):
    road = SHARED / "conformance/crg-txt/handmade_curved_banked_sloped.crg"
    fmu = pack(road, work / f"crg{fmi}.fmu", fmi)
    assert validate_fmu(str(fmu)) == []
    probe = crg_oracle(road)
    # The path along the road's own u/v (the road's 0 to 22 and a little beyond).
    table = wheel_path(road_xy(road))
    quantities = ["x", "y", "z", "u", "v", "heading", "curvature", "onRoad", "nx", "ny", "nz", "friction"]
    outputs = [f"wheel[{i}].{q}" for i in range(1, WHEELS + 1) for q in quantities]
    compared = 0
    for fmi_type in ("CoSimulation", "ModelExchange"):
        result = simulate(fmu, fmi_type, table, outputs)
        on_road = 0
        for row in result:
            for i in range(1, WHEELS + 1):
                want = probe(row[f"wheel[{i}].x"], row[f"wheel[{i}].y"])
                for q, value in want.items():
                    assert same(float(row[f"wheel[{i}].{q}"]), value), (fmi_type, i, q, row[f"wheel[{i}].{q}"], value)
                n = [row[f"wheel[{i}].n{c}"] for c in "xyz"]
                assert abs(math.hypot(*n) - 1.0) < 1e-12 and n[2] > 0.9
                assert row[f"wheel[{i}].friction"] == 1.0
                on_road += bool(row[f"wheel[{i}].onRoad"])
                compared += 1
        assert on_road > 0.5 * len(result) * WHEELS, (fmi_type, on_road)
    assert compared >= 2 * 150 * WHEELS


@pytest.mark.parametrize("fmi", [2, 3])
@pytest.mark.parametrize("mode", sorted(MODES))
def test_map_answers_as_odr_eval_and_the_c_api(work, mode, fmi):
    path = map_with(work, mode, MODES[mode] + FRICTION)
    bare = map_with(work, mode + "_bare", "")
    fmu = pack(path, work / f"{mode}{fmi}.fmu", fmi)
    assert validate_fmu(str(fmu)) == []
    # wheel[i].road is an enumeration whose items are named by the roads' OpenDRIVE ids.
    md = fmpy.read_model_description(str(fmu))
    road_type = next(t for t in md.typeDefinitions if t.name == "Road")
    item = {int(i.value): i.name for i in road_type.items}
    assert item[-1] == "off road" and item[0] == "1", item
    table = wheel_path(lambda s, t: road_points(path, 0, [s], [t])[0])
    quantities = ["x", "y", "z", "friction", "s", "t", "road", "lane", "onRoad", "nx", "ny", "nz"]
    outputs = [f"wheel[{i}].{q}" for i in range(1, WHEELS + 1) for q in quantities]
    friction_default = 0.85
    for fmi_type in ("CoSimulation", "ModelExchange"):
        result = simulate(fmu, fmi_type, table, outputs, {"frictionDefault": friction_default})
        moved, gripped = 0, 0
        for i in range(1, WHEELS + 1):
            probe, plain = map_oracle(path, friction_default), map_oracle(bare, friction_default)
            rows = [(float(row[f"wheel[{i}].x"]), float(row[f"wheel[{i}].y"]), row) for row in result]
            # odr eval given the wheel's positions in turn (each new one once).
            steps = [(x, y) for k, (x, y, _) in enumerate(rows) if k == 0 or (x, y) != rows[k - 1][:2]]
            odr = dict(zip(steps, cli("odr", "eval", path, stdin="".join(f"{x!r} {y!r}\n" for x, y in steps)).splitlines()))
            for x, y, row in rows:
                want = probe(x, y)
                for q, value in want.items():
                    assert same(float(row[f"wheel[{i}].{q}"]), float(value)), (mode, fmi_type, i, q, x, y)
                z, mu, road, s, t = odr[(x, y)].split()
                assert road == "1" or not want["onRoad"], road
                assert item[int(row[f"wheel[{i}].road"])] == (road if want["onRoad"] else "off road")
                for q, text in (("z", z), ("s", s), ("t", t)):
                    assert float(row[f"wheel[{i}].{q}"]) == float(text), (mode, q, text)
                if mu != "nan":
                    assert float(row[f"wheel[{i}].friction"]) == float(mu)
                    gripped += 1
                moved += plain(x, y)["z"] != want["z"]
        # The records were met: heights other than the bare road's, friction from the record.
        assert moved > 0.3 * len(result) * WHEELS, (mode, moved)
        assert gripped > 0.3 * len(result) * WHEELS, (mode, gripped)


def test_a_get_after_a_set_answers_at_once_and_bad_calls_are_refused(work):
    fmu = pack(work / "rough.crg", work / "rough.fmu", 2)
    md = fmpy.read_model_description(str(fmu))
    vr = {v.name: v.valueReference for v in md.modelVariables}
    unzipped = fmpy.extract(str(fmu))
    said = []
    callbacks = fmi2CallbackFunctions()
    callbacks.logger = fmi2CallbackLoggerTYPE(lambda env, name, status, cat, msg: said.append(msg.decode()))
    slave = FMU2Slave(guid=md.guid, unzipDirectory=unzipped, modelIdentifier=md.coSimulation.modelIdentifier,
                      instanceName="a")
    slave.instantiate(callbacks=callbacks)
    with pytest.raises(Exception):
        slave.getReal([vr["wheel[1].z"]])
    assert any("fmi2GetReal" in m and "not allowed" in m for m in said), said
    # A choice out of range: refused with the C API's message, the value kept as it was.
    with pytest.raises(Exception):
        slave.setInteger([vr["options.BORDER_MODE_V"]], [99])
    assert any("<border mode v> = 99 is not one of its choices 0 to 4" in m for m in said), said
    slave.setupExperiment(startTime=0.0)
    slave.enterInitializationMode()
    slave.exitInitializationMode()
    start = next(v.start for v in md.modelVariables if v.name == "options.BORDER_MODE_V")
    assert slave.getInteger([vr["options.BORDER_MODE_V"]]) == [int(start)]
    probe = crg_oracle(work / "rough.crg")
    for x, y in ((231.0, 152.0), (235.0, 160.0), (232.0, 155.5)):
        slave.setReal([vr["wheel[2].x"], vr["wheel[2].y"]], [x, y])
        # No step between the set and the get.
        assert slave.getReal([vr["wheel[2].z"], vr["wheel[2].u"]]) == [probe(x, y)["z"], probe(x, y)["u"]]
    # One call naming wheel variables and a parameter, the parameter between them: each
    # taken in turn (the wheels' references by their tables, the rest the other way).
    x, y = 233.0, 157.0
    slave.setReal([vr["wheel[2].x"], vr["frictionDefault"], vr["wheel[2].y"]], [x, 0.7, y])
    got = slave.getReal([vr["wheel[2].z"], vr["frictionDefault"], vr["wheel[2].u"], vr["wheel[2].y"]])
    assert got == [probe(x, y)["z"], 0.7, probe(x, y)["u"], y]
    # The same position set again keeps the answer; another one gives its own.
    slave.setReal([vr["wheel[2].x"], vr["wheel[2].y"]], [x, y])
    assert slave.getReal([vr["wheel[2].z"]]) == [probe(x, y)["z"]]
    slave.setReal([vr["wheel[2].y"]], [y + 1.0])
    assert slave.getReal([vr["wheel[2].z"]]) == [probe(x, y + 1.0)["z"]]
    slave.setReal([vr["wheel[3].x"]], [float("nan")])
    assert slave.getBoolean([vr["wheel[3].onRoad"]]) == [False]
    assert slave.getReal([vr["wheel[3].z"], vr["wheel[3].nz"]]) == [0.0, 1.0]
    # Infinite positions: finite outputs, off the road.
    outputs = ["z", "u", "v", "nx", "ny", "nz", "heading", "curvature", "friction"]
    for x, y in ((float("inf"), 150.0), (231.0, float("-inf")), (float("inf"), float("nan"))):
        slave.setReal([vr["wheel[3].x"], vr["wheel[3].y"]], [x, y])
        assert slave.getBoolean([vr["wheel[3].onRoad"]]) == [False]
        got = slave.getReal([vr[f"wheel[3].{q}"] for q in outputs])
        assert all(math.isfinite(g) for g in got), (x, y, got)
    said.clear()
    with pytest.raises(Exception):
        slave.getReal([99999])
    assert any("99999" in m for m in said), said
    with pytest.raises(Exception):
        slave.setReal([vr["wheel[1].z"]], [1.0])
    with pytest.raises(Exception):
        slave.setString([vr["compat"]], ["2.0.1"])
    assert any("fixed parameter compat" in m for m in said), said
    slave.terminate()
    slave.freeInstance()
    shutil.rmtree(unzipped, ignore_errors=True)


def test_an_fmu_unpacked_where_names_have_spaces_and_accents_works(work):
    fmu = pack(work / "flat.crg", work / "flat.fmu", 2)
    folder = work / "unpacked here" / "Straße"
    fmpy.extract(str(fmu), unzipdir=str(folder))
    table = wheel_path(lambda s, t: (-40.0 + s * 0.1, 25.0 + t))
    result = fmpy.simulate_fmu(str(folder), input=table, output=["wheel[1].z", "wheel[1].onRoad"],
                               step_size=DT, stop_time=float(table["time"][-1]))
    assert result["wheel[1].onRoad"].any()
    fmu3 = pack(work / "flat.crg", work / "flat3.fmu", 3)
    folder3 = work / "unpacked here" / "Ünïcode 3"
    fmpy.extract(str(fmu3), unzipdir=str(folder3))
    result = fmpy.simulate_fmu(str(folder3), input=table, output=["wheel[1].z", "wheel[1].onRoad"],
                               step_size=DT, stop_time=float(table["time"][-1]))
    assert result["wheel[1].onRoad"].any()


def drive(fmu_path, points, answers, errors):
    """One instance on its own thread: its wheel 1 along `points`."""
    try:
        md = fmpy.read_model_description(str(fmu_path))
        vr = {v.name: v.valueReference for v in md.modelVariables}
        unzipped = fmpy.extract(str(fmu_path))
        slave = FMU3Slave(guid=md.guid, unzipDirectory=unzipped, modelIdentifier=md.coSimulation.modelIdentifier)
        slave.instantiate()
        slave.enterInitializationMode()
        slave.exitInitializationMode()
        for k, (x, y) in enumerate(points):
            slave.setFloat64([vr["wheel[1].x"], vr["wheel[1].y"]], [x, y])
            slave.doStep(k * DT, DT)
            answers.append(slave.getFloat64([vr["wheel[1].z"]])[0])
        slave.terminate()
        slave.freeInstance()
    except Exception as e:  # noqa: BLE001 - reported by the test
        errors.append(repr(e))


def test_two_instances_of_different_roads_on_two_threads_answer_their_own(work):
    crg = pack(work / "rough.crg", work / "two_a.fmu", 3)
    path = map_with(work, "two", MODES["genuine"] + FRICTION)
    odr = pack(path, work / "two_b.fmu", 3)
    crg_points = [(231.0 + 0.01 * k, 152.0 + 0.03 * k) for k in range(2000)]
    map_points = road_points(path, 0, [100.0 + 0.025 * k for k in range(2000)], [0.5] * 2000)
    a, b, errors = [], [], []
    threads = [threading.Thread(target=drive, args=(crg, crg_points, a, errors)),
               threading.Thread(target=drive, args=(odr, map_points, b, errors))]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    assert errors == []
    crg_probe, map_probe = crg_oracle(work / "rough.crg"), map_oracle(path, 1.0)
    assert a == [crg_probe(x, y)["z"] for x, y in crg_points]
    assert b == [map_probe(x, y)["z"] for x, y in map_points]


@pytest.mark.parametrize("fmi", [2, 3])
def test_an_fmu_lacking_its_crg_file_is_refused_at_instantiation(work, fmi):
    path = map_with(work, "broken", MODES["attached"])
    whole = pack(path, work / f"whole{fmi}.fmu", fmi)
    broken = work / f"broken{fmi}.fmu"
    with zipfile.ZipFile(whole) as src, zipfile.ZipFile(broken, "w") as dst:
        for item in src.infolist():
            if not item.filename.endswith("flat.crg"):
                dst.writestr(item, src.read(item))
    md = fmpy.read_model_description(str(broken))
    unzipped = fmpy.extract(str(broken))
    said = []
    with pytest.raises(Exception):
        instantiated(md, unzipped, fmi, said)
    assert len(said) == 1 and "flat.crg" in said[0] and "cannot read" in said[0], said
    # The process goes on: the whole FMU still simulates.
    table = wheel_path(lambda s, t: road_points(path, 0, [s], [t])[0], n=20)
    result = simulate(str(whole), "CoSimulation", table, ["wheel[1].onRoad"])
    assert result["wheel[1].onRoad"].all()
    shutil.rmtree(unzipped, ignore_errors=True)


@pytest.mark.parametrize("fmi", [2, 3])
def test_a_road_left_outside_the_fmu_is_read_in_place_where_it_lies(work, fmi, monkeypatch):
    monkeypatch.setenv("OPENCRG_IN_PLACE", "always")
    source = SHARED / "conformance/crg-txt/handmade_curved_banked_sloped.crg"
    road = work / f"outside{fmi}.crg"
    cli("convert", source, road, "--format", "KRBI")
    fmu = work / f"outside{fmi}.fmu"
    cli("fmu", road, fmu, "--fmi", fmi, "--wheels", WHEELS, "--road-outside")
    with zipfile.ZipFile(fmu) as z:
        assert not [n for n in z.namelist() if n.endswith(".crg")], z.namelist()
    assert validate_fmu(str(fmu)) == []
    md = fmpy.read_model_description(str(fmu))
    start = {v.name: v.start for v in md.modelVariables}
    assert start["roadFile"] == str(road.resolve())
    probe = crg_oracle(road)
    table = wheel_path(road_xy(road), n=60)
    outputs = [f"wheel[{i}].{q}" for i in range(1, WHEELS + 1) for q in ("x", "y", "z", "u", "v")]

    def answers_as_the_c_api(result):
        for row in result:
            for i in range(1, WHEELS + 1):
                want = probe(row[f"wheel[{i}].x"], row[f"wheel[{i}].y"])
                for q in ("z", "u", "v"):
                    assert same(float(row[f"wheel[{i}].{q}"]), want[q]), (i, q)

    answers_as_the_c_api(simulate(fmu, "CoSimulation", table, outputs))
    # The road moved: instantiation goes on, initialization is refused naming the file
    # and the parameter, until roadFile names where the road lies now.
    moved = work / f"moved{fmi}" / "road.crg"
    moved.parent.mkdir(exist_ok=True)
    road.rename(moved)
    unzipped = fmpy.extract(str(fmu))
    said = []
    slave = instantiated(md, unzipped, fmi, said)
    if fmi == 2:
        slave.setupExperiment()
    with pytest.raises(Exception):
        slave.enterInitializationMode()
    assert any(road.name in m and "roadFile" in m for m in said), said
    slave.freeInstance()
    shutil.rmtree(unzipped, ignore_errors=True)
    answers_as_the_c_api(simulate(fmu, "CoSimulation", table, outputs, start_values={"roadFile": str(moved)}))


@pytest.mark.parametrize("fmi", [2, 3])
def test_model_exchange_changes_discrete_outputs_at_events_its_indicators_announce(work, fmi):
    """onRoad (a discrete output) holds in continuous-time mode; the wheel's event
    indicator turns -1 when it would change; at the event it takes the new value."""
    fmu = pack(work / "rough.crg", work / f"events{fmi}.fmu", fmi, wheels=2)
    md = fmpy.read_model_description(str(fmu))
    vr = {v.name: v.valueReference for v in md.modelVariables}
    if fmi == 2:
        assert md.numberOfEventIndicators == 2
    else:
        assert [e.variable.name for e in md.eventIndicators] == ["wheel[1].eventIndicator", "wheel[2].eventIndicator"]
    unzipped = fmpy.extract(str(fmu))
    model_class = FMU2Model if fmi == 2 else FMU3Model
    model = model_class(guid=md.guid, unzipDirectory=unzipped, modelIdentifier=md.modelExchange.modelIdentifier)
    model.instantiate()
    set_real = model.setReal if fmi == 2 else model.setFloat64
    on, off = (231.0, 152.0), (1e5, 1e5)
    if fmi == 2:
        model.setupExperiment(startTime=0.0)
        model.enterInitializationMode()
    else:
        model.enterInitializationMode(startTime=0.0)
    set_real([vr["wheel[1].x"], vr["wheel[1].y"], vr["wheel[2].x"], vr["wheel[2].y"]], [*on, *on])
    model.exitInitializationMode()
    model.newDiscreteStates() if fmi == 2 else model.updateDiscreteStates()
    model.enterContinuousTimeMode()
    z = (ctypes.c_double * 2)()

    def indicators():
        model.getEventIndicators(z, 2)
        return list(z)

    on_road = [vr["wheel[1].onRoad"], vr["wheel[2].onRoad"]]
    assert model.getBoolean(on_road) == [True, True] and indicators() == [1.0, 1.0]
    # Wheel 2 leaves the road between events: its output holds, its indicator says so.
    model.setTime(0.1)
    set_real([vr["wheel[2].x"], vr["wheel[2].y"]], list(off))
    assert model.getBoolean(on_road) == [True, True]
    assert indicators() == [1.0, -1.0]
    # The event: the new value, the indicator back to 1.
    model.enterEventMode()
    model.newDiscreteStates() if fmi == 2 else model.updateDiscreteStates()
    assert model.getBoolean(on_road) == [True, False]
    model.enterContinuousTimeMode()
    assert model.getBoolean(on_road) == [True, False] and indicators() == [1.0, 1.0]
    # Back onto the road.
    set_real([vr["wheel[2].x"], vr["wheel[2].y"]], list(on))
    assert model.getBoolean(on_road) == [True, False] and indicators() == [1.0, -1.0]
    model.terminate()
    model.freeInstance()
    shutil.rmtree(unzipped, ignore_errors=True)
