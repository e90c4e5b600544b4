#!/usr/bin/env python3
"""Compares the conformance client's answers with others to the last bit.

usage: same_bits.py GOLDEN_DIR ACTUAL_DIR [ALLOWED]

Every number of GOLDEN_DIR/NAME.txt must equal the one of ACTUAL_DIR/NAME.txt exactly
(NaN with NaN), every refusal code likewise; the values of a refused call are not
compared (the C client prints 0, others NaN). Prints the cases that differ with their
first difference, then 'N cases, K differ in M lines' last; exit status 1 when more
than ALLOWED cases (default 0) differ.
"""
import math
import os
import sys


def same(a, b):
    try:
        x, y = float(a), float(b)
    except ValueError:
        return a == b
    return (math.isnan(x) and math.isnan(y)) or x == y


def same_line(g, a):
    """The same answers in one line: groups split by '|', each a code and its values."""
    gs, as_ = g.split("|"), a.split("|")
    if len(gs) != len(as_):
        return False
    for n, (gg, aa) in enumerate(zip(gs, as_)):
        gw, aw = gg.split(), aa.split()
        if n > 0 and gw[:1] == ["0"] and aw[:1] == ["0"]:
            continue
        if len(gw) != len(aw) or not all(map(same, gw, aw)):
            return False
    return True


def main():
    golden, actual = sys.argv[1], sys.argv[2]
    allowed = int(sys.argv[3]) if len(sys.argv) > 3 else 0
    names = sorted(n for n in os.listdir(golden) if n.endswith(".txt"))
    cases, points = 0, 0
    for name in names:
        g = open(os.path.join(golden, name)).read().split("\n")
        path = os.path.join(actual, name)
        a = open(path).read().split("\n") if os.path.exists(path) else []
        differing = [
            (n, gl, al)
            for n, (gl, al) in enumerate(zip(g, a), 1)
            if not same_line(gl, al)
        ]
        if len(g) != len(a):
            differing.append((0, f"{len(g)} lines", f"{len(a)} lines"))
        if differing:
            cases += 1
            points += len(differing)
            n, gl, al = differing[0]
            print(f"{name[:-4]}: {len(differing)} lines differ; line {n}: '{al}' where golden has '{gl}'")
    print(f"{len(names)} cases, {cases} differ in {points} lines")
    return 1 if cases > allowed else 0


if __name__ == "__main__":
    sys.exit(main())
