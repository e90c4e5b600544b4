"""1 M random uv_to_z and xy_to_uv points in Python: this project's `opencrg` package
against pycrg (the reference C library, wrapped) and PyOpenCRG (pure Python and numpy),
each installed beforehand (`pip install crates/opencrg-python pycrg PyOpenCRG`).
A package that is not installed is reported as such, not timed.

usage: python bench/python_bench.py ROAD.crg [N]
The README's figures: the 500 m road of bench/compare.sh (target/bench-roads/track_500m_krbi.crg).
"""

import importlib
import sys
import time

import numpy as np


def timed(f):
    t = time.perf_counter()
    out = f()
    return time.perf_counter() - t, out


def main():
    path = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 1_000_000
    import opencrg

    road = opencrg.Road(path)
    road.apply_modifiers()
    rng = np.random.default_rng(42)
    (u0, u1), (v0, v1) = road.u_range, road.v_range
    u = rng.uniform(u0, u1, n)
    v = rng.uniform(v0, v1, n)
    x, y = road.uv_to_xy(u, v)

    def ours():
        cp = opencrg.ContactPoint(road)
        return cp.uv_to_z, cp.xy_to_uv

    def pycrg():
        m = importlib.import_module("pycrg")
        cp = m.DataSet.open(path).create_contact_point()
        return cp.uv_to_z_many, cp.xy_to_uv_many

    def pyopencrg():
        m = importlib.import_module("pyopencrg")
        r = m.read(path)
        return r.uv_to_z, r.xy_to_uv

    rows = []
    reference = None
    for name, make in [("opencrg (this project)", ours), ("pycrg 2.2.0", pycrg), ("PyOpenCRG 0.2.2", pyopencrg)]:
        try:
            uv_to_z, xy_to_uv = make()
        except ImportError as e:
            rows.append((name, f"not installed ({e.name})", "", ""))
            continue
        t_z, z = timed(lambda: uv_to_z(u, v))
        t_uv, (uu, vv) = timed(lambda: xy_to_uv(x, y))
        z = np.asarray(z)
        if reference is None:
            reference = z
        diff = np.nanmax(np.abs(z - reference))
        rows.append((name, f"{t_z:.3f} s ({n / t_z / 1e6:.1f} M/s)", f"{t_uv:.3f} s ({n / t_uv / 1e6:.2f} M/s)",
                     f"{diff:.1e}"))
    print(f"{n} random points on {path}, one run each")
    print(f"{'package':<24} {'uv_to_z':<24} {'xy_to_uv':<24} max |z - ours|")
    for r in rows:
        print(f"{r[0]:<24} {r[1]:<24} {r[2]:<24} {r[3]}")


if __name__ == "__main__":
    main()
