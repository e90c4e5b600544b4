"""FMUs of `opencrg fmu` in two co-simulation engines nobody here wrote: ECOS (ecospy,
FMI 2 and 3, through fmi4c) and libcosim (libcosimpy, FMI 2, through FMI Library).

One system holds two FMUs of different roads, a CRG file and a map with CRG records.
Their wheels are set along their own roads, onto the other FMU's road, off both, to
infinite and NaN positions; after each step every output of each FMU equals what the
C API answers for its own road at that wheel's x/y, to the bit, and an infinite or NaN
position gives finite outputs with `onRoad` false.

Needs what test_fmpy.py needs, and the pip packages ecospy (its library wants Debian's
libtbb12) and libcosimpy.
"""

import math

import pytest
from test_fmpy import FRICTION, MODES, crg_oracle, map_oracle, map_with, pack, road_points, road_xy, same, work  # noqa: F401

WHEELS = 4
CRG_QUANTITIES = ("z", "u", "v", "heading", "curvature")
MAP_QUANTITIES = ("z", "friction", "s", "t", "lane", "nx", "ny", "nz")
FRICTION_DEFAULT = 0.85
STRANGE = [(math.inf, 150.0), (231.0, -math.inf), (math.nan, 3.0), (math.inf, math.nan)]


def positions(crg_xy, map_xy):
    """Each step's positions of the four wheels: along the road, on the other road, off
    both, infinite and NaN; the wheels' positions differ within a step."""
    steps = []
    for k in range(40):
        own = [crg_xy(91.0 + k + 0.5 * i, (-1.0) ** i * 0.7 * i) for i in range(WHEELS)]
        steps.append(own)
    for k in range(10):
        steps.append([map_xy(110.0 + 4 * k + i, 0.3 * i) for i in range(WHEELS)])
    steps.append([(1.0e6, -2.0e6), (0.0, 0.0), (-500.0, 500.0), (230.0, 900.0)])
    steps += [[STRANGE[(k + i) % len(STRANGE)] for i in range(WHEELS)] for k in range(len(STRANGE))]
    steps.append([crg_xy(95.0 + i, 0.0) for i in range(WHEELS)])
    return steps


@pytest.fixture(scope="module")
def system(work):
    """The two roads (a CRG file, a map with CRG records) and the wheels' positions step by step."""
    crg = work / "rough.crg"
    odr = map_with(work, "importers", MODES["genuine"] + FRICTION)
    crg_xy = road_xy(crg)

    def map_xy(s, t):
        return road_points(odr, 0, [s], [t])[0]

    return {"crg": crg, "odr": odr, "steps": positions(crg_xy, map_xy)}


QUANTITIES = {"crg": CRG_QUANTITIES, "map": MAP_QUANTITIES}


def check_step(step, got_crg, got_map, on_road_crg, on_road_map, crg_probes, map_probes):
    """One step's outputs of both FMUs against their own roads' C API answers."""
    for i, (x, y) in enumerate(step):
        finite = math.isfinite(x) and math.isfinite(y)
        if finite:
            want = crg_probes[i](x, y)
            for q in CRG_QUANTITIES:
                assert same(got_crg[i][q], want[q]), ("crg", i, q, x, y, got_crg[i][q], want[q])
            want = map_probes[i](x, y)
            for q in MAP_QUANTITIES:
                assert same(got_map[i][q], float(want[q])), ("map", i, q, x, y, got_map[i][q], want[q])
            assert on_road_map[i] == want["onRoad"], (i, x, y)
        else:
            for got in (got_crg[i], got_map[i]):
                assert all(math.isfinite(v) for v in got.values()), (i, x, y, got)
            assert not on_road_crg[i] and not on_road_map[i], (i, x, y)


def drive(system, place, advance, read):
    """Both FMUs through the steps in an engine: `place(model, step)` sets a model's
    wheels, `advance()` steps the engine, `read(model)` gives the model's quantities
    (`QUANTITIES`) of each wheel and each wheel's onRoad; every step checked."""
    crg_probes = [crg_oracle(system["crg"]) for _ in range(WHEELS)]
    map_probes = [map_oracle(system["odr"], FRICTION_DEFAULT) for _ in range(WHEELS)]
    on_road = 0
    for step in system["steps"]:
        for model in QUANTITIES:
            place(model, step)
        advance()
        (got_crg, crg_flags), (got_map, map_flags) = read("crg"), read("map")
        check_step(step, got_crg, got_map, crg_flags, map_flags, crg_probes, map_probes)
        on_road += sum(crg_flags)
    assert on_road >= 40 * WHEELS * 0.5, on_road


@pytest.mark.parametrize("fmi", [2, 3])
def test_ecos_runs_fmus_of_two_roads_in_one_system(work, system, fmi):
    from ecospy import EcosSimulation, EcosSimulationStructure

    structure = EcosSimulationStructure()
    structure.add_model("crg", str(pack(system["crg"], work / f"ecos_crg{fmi}.fmu", fmi)))
    structure.add_model("map", str(pack(system["odr"], work / f"ecos_map{fmi}.fmu", fmi)))
    with EcosSimulation(structure=structure, step_size=0.01) as sim:

        def place(model, step):
            for i, (x, y) in enumerate(step, 1):
                sim.set_real(f"{model}::wheel[{i}].x", x)
                sim.set_real(f"{model}::wheel[{i}].y", y)

        def value(model, i, q):
            name = f"{model}::wheel[{i}].{q}"
            return float(sim.get_integer(name)) if q == "lane" else sim.get_real(name)

        def read(model):
            wheels = range(1, WHEELS + 1)
            return ([{q: value(model, i, q) for q in QUANTITIES[model]} for i in wheels],
                    [sim.get_bool(f"{model}::wheel[{i}].onRoad") for i in wheels])

        sim.set_real("map::frictionDefault", FRICTION_DEFAULT)
        # The wheels start where the first step puts them: the engine reads the outputs
        # at initialisation, and a wheel's search starts from where it was last asked.
        for model in QUANTITIES:
            place(model, system["steps"][0])
        sim.init()
        drive(system, place, sim.step, read)
        sim.terminate()


def test_libcosim_runs_fmus_of_two_roads_in_one_system(work, system):
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimManipulator import CosimManipulator
    from libcosimpy.CosimObserver import CosimObserver
    from libcosimpy.CosimSlave import CosimLocalSlave

    log_output_level(CosimLogLevel.WARNING)
    execution = CosimExecution.from_step_size(step_size=10_000_000)
    index, refs = {}, {}
    for model, road in (("crg", system["crg"]), ("map", system["odr"])):
        fmu = pack(road, work / f"cosim_{model}.fmu", 2)
        index[model] = execution.add_local_slave(CosimLocalSlave(fmu_path=str(fmu), instance_name=model))
        refs[model] = {v.name.decode(): v.reference for v in execution.slave_variables(index[model])}
    manipulator, observer = CosimManipulator.create_override(), CosimObserver.create_last_value()
    assert execution.add_manipulator(manipulator) and execution.add_observer(observer)
    assert execution.real_initial_value(index["map"], refs["map"]["frictionDefault"], FRICTION_DEFAULT)
    for model in QUANTITIES:
        for i, (x, y) in enumerate(system["steps"][0], 1):
            assert execution.real_initial_value(index[model], refs[model][f"wheel[{i}].x"], x)
            assert execution.real_initial_value(index[model], refs[model][f"wheel[{i}].y"], y)

    def vrs(model, q):
        return [refs[model][f"wheel[{i}].{q}"] for i in range(1, WHEELS + 1)]

    def place(model, step):
        xy = [refs[model][f"wheel[{i}].{c}"] for i in range(1, WHEELS + 1) for c in "xy"]
        assert manipulator.slave_real_values(index[model], xy, [c for at in step for c in at])

    def read(model):
        # libcosim reads an FMU's outputs after its step; lane is an Integer in FMI 2.
        columns = {q: observer.last_integer_values(index[model], vrs(model, q)) if q == "lane"
                   else observer.last_real_values(index[model], vrs(model, q)) for q in QUANTITIES[model]}
        wheels = [{q: float(columns[q][i]) for q in QUANTITIES[model]} for i in range(WHEELS)]
        return wheels, list(observer.last_boolean_values(index[model], vrs(model, "onRoad")))

    def advance():
        assert execution.step()

    drive(system, place, advance, read)
