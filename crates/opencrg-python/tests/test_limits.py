"""Requests one typo away from sensible ones: each raises opencrg.RequestError (a
ValueError) before anything is allocated, and the interpreter lives on; the same in a
child interpreter limited to 2 GB of address space."""

import math
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import opencrg


def line():
    x = np.arange(0.0, 201.0, 2.0)
    return np.column_stack([x, 20.0 * np.sin(x / 40.0)])


def cloud():
    x, y = np.meshgrid(np.arange(0.0, 100.0, 0.5), np.arange(-3.0, 3.01, 0.3))
    return np.column_stack([x.ravel(), y.ravel(), 0.01 * np.sin(x.ravel())])


def stray_cloud():
    """The cloud with two stray points 6,000 km away."""
    return np.vstack([cloud(), [[6.0e6, 0.0, 0.0], [20.0, -6.0e6, 0.0]]])


# (what, call, words the message holds)
ABSURD = [
    ("resample u_inc=1e-9", lambda r: r.resample(u_inc=1e-9), ["1e-9 m", "the limit is", "max_memory="]),
    ("resample 1e-7 x 1e-7", lambda r: r.resample(u_inc=1e-7, v_inc=1e-7), ["the limit is"]),
    ("resample u_inc=-1", lambda r: r.resample(u_inc=-1), ["-1 m must be a positive number"]),
    ("resample v_inc=nan", lambda r: r.resample(v_inc=math.nan), ["NaN"]),
    ("resample max_memory=1000", lambda r: r.resample(u_inc=0.1, max_memory=1000), ["the limit is 1.00 kB"]),
    ("resample max_memory='1KiB'", lambda r: r.resample(u_inc=0.1, max_memory="1KiB"), ["the limit is 1.02 kB"]),
    ("resample max_memory=-5", lambda r: r.resample(max_memory=-5), ["max_memory=-5"]),
    ("resample max_memory='lots'", lambda r: r.resample(max_memory="lots"), ["expected bytes"]),
    ("generate u_inc=1e-9", lambda r: opencrg.generate(line(), 3.0, 1e-9, 0.1), ["1e-9 m", "the limit is"]),
    ("generate v_inc=1e-11", lambda r: opencrg.generate(line(), 3.0, 0.1, 1e-11), ["1e-11 m"]),
    ("generate width=3e9", lambda r: opencrg.generate(line(), 3e9, 0.1, 0.1), ["3e9 m wide"]),
    ("import u_inc=1e-9", lambda r: opencrg.import_points(cloud(), 1e-9, 0.1), ["1e-9 m"]),
    ("import width=1e12", lambda r: opencrg.import_points(cloud(), 0.1, 0.1, width=1e12), ["1e12 m wide"]),
    ("import stray points", lambda r: opencrg.import_points(stray_cloud(), 1.0, 1.0), ["stray points?", "crop to x"]),
    ("import crop=empty", lambda r: opencrg.import_points(cloud(), 1.0, 1.0, crop=((0, 1), (5, 6))), ["at least three"]),
    ("filter median=1000001", lambda r: r.filter(median=1000001), ["wider than the road"]),
    ("filter median=-3", lambda r: r.filter(median=-3), ["median window -3"]),
    ("filter gauss=1e9", lambda r: r.filter(gauss=1e9), ["beyond the road"]),
    ("roughness segment=1e-300", lambda r: r.roughness(segment=1e-300), ["segment length 1e-300 m"]),
    ("roughness tracks=[1e300]", lambda r: r.roughness(tracks=[1e300]), ["outside the road"]),
    ("iri segment=1e-300", lambda r: opencrg.iri(np.zeros(1000), 0.05, segment=1e-300), ["segment length"]),
    ("to_mesh max_memory=1000", lambda r: r.to_mesh(max_memory=1000), ["vertices", "the limit is"]),
    ("to_mesh max_error max_memory", lambda r: r.to_mesh(max_error=0.001, max_memory=1000), ["lattice points"]),
    ("cut u=(1e300, 2e300)", lambda r: r.cut((1e300, 2e300)), ["1e300:2e300"]),
    ("ContactPoint history=2**62", lambda r: opencrg.ContactPoint(r, history=2**62), ["search history"]),
]


@pytest.mark.parametrize("what,call,words", ABSURD, ids=[a[0] for a in ABSURD])
def test_absurd_requests_raise_request_errors(road_file, what, call, words):
    road = opencrg.Road(road_file)
    with pytest.raises(opencrg.RequestError) as e:
        call(road)
    assert isinstance(e.value, ValueError) and isinstance(e.value, opencrg.CrgError)
    # The kind: beyond the memory limit, or a value the request does not take.
    beyond = "the limit is" in str(e.value)
    assert isinstance(e.value, opencrg.TooLargeError if beyond else opencrg.OutOfRangeError), type(e.value)
    assert isinstance(e.value, MemoryError) == beyond
    for w in words:
        assert w in str(e.value), (w, str(e.value))
    # The interpreter and the road still answer.
    assert road.resample(u_inc=0.5).increments[0] == 0.5


def test_a_limited_interpreter_survives_every_absurd_request(road_file, tmp_path):
    """A child Python under 2 GB of address space runs the whole table and then works on."""
    script = textwrap.dedent(f"""
        import resource, math, sys
        resource.setrlimit(resource.RLIMIT_AS, (2_000_000_000, 2_000_000_000))
        import numpy as np
        sys.path.insert(0, {str(tmp_path)!r})
        import opencrg
        from test_limits_table import ABSURD
        road = opencrg.Road({str(road_file)!r})
        refused = 0
        for what, call, words in ABSURD:
            try:
                call(road)
            except opencrg.RequestError:
                refused += 1
        print(refused, len(ABSURD), road.resample(u_inc=0.5).increments[0])
    """)
    # The table, importable by the child without pytest.
    source = open(__file__).read()
    table = source[source.index("def line():"):source.index("@pytest.mark")]
    (tmp_path / "test_limits_table.py").write_text("import math\nimport numpy as np\nimport opencrg\n\n" + table)
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    refused, total, inc = out.stdout.split()
    assert refused == total and float(inc) == 0.5, out.stdout
    for bad in ["panicked", "memory allocation", "Traceback"]:
        assert bad not in out.stderr, out.stderr
