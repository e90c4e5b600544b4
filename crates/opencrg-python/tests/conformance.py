"""The conformance suite's client (../shared/conformance/oracle.c) on the Python package:
the same questions in the same order on one contact point, printed so that the suite's
compare.py (within its tolerance) and c-tests/generated/same_bits.py (to the last bit)
read the answers as the C client's.

    python conformance.py SUITE OUT [current|2.0.1]

SUITE holds cases.txt and the roads it names; OUT receives one NAME.txt a case.
"""

import math
import pathlib
import sys

import opencrg

# The settings the client sets as integers (as the C client's table does); every other
# one is a double.
INTEGER_SETTINGS = {"border_mode_u", "border_mode_v", "curv_mode", "refline_continuation", "grid_nan_mode"}


def setting(text):
    """`mod:NAME=VALUE` or `opt:NAME=VALUE` as (kind, Python name, value)."""
    kind, rest = text.split(":", 1)
    name, value = rest.split("=", 1)
    name = name.lower()
    number = float(value)
    return kind, name, int(number) if name in INTEGER_SETTINGS else number


def number(x):
    return " nan" if math.isnan(x) else f" {x!r}"


def answers(path, nu, nv, settings, compat):
    """The client's output for one case, as lines."""
    try:
        road = opencrg.Road(path, compat=compat)
    except Exception:
        return ["load 0"]
    lines = ["load 1"]
    try:
        road.check()
        lines.append("check 1")
    except opencrg.CheckError:
        lines.append("check 0")
    parsed = [setting(s) for s in settings]
    modifiers = [(name, value) for kind, name, value in parsed if kind == "mod"]
    if modifiers:
        road.clear_modifiers()
    for name, value in modifiers:
        road.set_modifier(name, value)
    road.apply_modifiers()
    cp = opencrg.ContactPoint(road, **{name: value for kind, name, value in parsed if kind == "opt"})
    lines.append("cp 1")
    (umin, umax), (vmin, vmax) = road.u_range, road.v_range
    uinc, vinc = road.increments
    closed, cmin, cmax = road.closed_track_report
    lines += [
        f"urange 1{number(umin)}{number(umax)}",
        f"vrange 1{number(vmin)}{number(vmax)}",
        f"incs 1{number(uinc)}{number(vinc)}",
        f"closed 1 {int(closed)}{number(cmin)}{number(cmax)}",
    ]
    length, width = umax - umin, vmax - vmin

    def ask(call, a, b):
        """The call's values as a tuple, and 1 where answered, 0 where refused."""
        values = call(a, b)
        return (values if isinstance(values, tuple) else (values,)), 0 if cp.refused else 1

    nan = math.nan
    for i in range(nu + 1):
        for j in range(nv + 1):
            # The grid reaches 30 % of the length and 40 % of the width past every border.
            u = umin - 0.3 * length + 1.6 * length * i / nu
            v = vmin - 0.4 * width + 1.8 * width * j / nv
            (x, y), r1 = ask(cp.uv_to_xy, u, v)
            (z,), r2 = ask(cp.uv_to_z, u, v)
            (phi, curv), r3 = ask(cp.uv_to_pk, u, v)
            (u2, v2), r4, (z2,), r5, (phi2, curv2), r6 = (nan, nan), 0, (nan,), 0, (nan, nan), 0
            if r1:
                (u2, v2), r4 = ask(cp.xy_to_uv, x, y)
                (z2,), r5 = ask(cp.xy_to_z, x, y)
                (phi2, curv2), r6 = ask(cp.xy_to_pk, x, y)
            lines.append(
                f"q{number(u)}{number(v)} | {r1}{number(x)}{number(y)} | {r2}{number(z)}"
                f" | {r3}{number(phi)}{number(curv)} | {r4}{number(u2)}{number(v2)} | {r5}{number(z2)}"
                f" | {r6}{number(phi2)}{number(curv2)}"
            )
    return lines


def main(suite, out, profile="current"):
    suite, out = pathlib.Path(suite), pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    compat = "2.0.1" if profile == "2.0.1" else "upstream"
    for line in (suite / "cases.txt").read_text().splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        name, file, nu, nv, *settings = line.split()
        lines = answers(suite / file, int(nu), int(nv), settings, compat)
        (out / f"{name}.txt").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main(*sys.argv[1:])
