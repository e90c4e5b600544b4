#!/usr/bin/env python3
"""Summarises the output of bench/vehicle_compare.sh (and bench/in_place.sh): per road and
case, the median and range (min-max) over the runs of the time per call and the medians of
the latency quantiles, for the base ("opencrg", or BASE) and the other one, and the ratio
of the times of each pair of runs taken in turn (other / base: how many times faster the
base is), its median and range.

usage: vehicle_report.py RESULTS   (lines "ROAD LIB RUN case CALL SPEED MODE THREADS ns N
p50 N p99 N p999 N max N" and "ROAD LIB RUN cpu MODEL"); MARKDOWN=1 prints Markdown tables;
BASE=LABEL names the base (default opencrg).
"""
import os
import statistics
import sys


def main(path):
    cpu, rows = set(), {}
    for line in open(path):
        f = line.split()
        if len(f) > 4 and f[3] == "cpu":
            cpu.add(" ".join(f[4:]))
        if len(f) < 9 or f[3] != "case":
            continue
        road, lib, run, case = f[0], f[1], f[2], " ".join(f[4:8])
        values = dict(zip(f[8::2], map(float, f[9::2])))
        values["run"] = run
        rows.setdefault(road, {}).setdefault(case, {}).setdefault(lib, []).append(values)
    markdown = os.environ.get("MARKDOWN") == "1"
    print(f"processor: {', '.join(sorted(cpu))}")

    def fig(runs, key):
        vals = [r[key] for r in runs]
        return statistics.median(vals), min(vals), max(vals)

    for road, cases in rows.items():
        base = os.environ.get("BASE", "opencrg")
        libs = sorted({lib for per in cases.values() for lib in per}, key=lambda l: l != base)
        print(f"\n{road} ({max(len(r) for per in cases.values() for r in per.values())} runs per library)\n")
        head = ["call", "m/s", "contact points", "threads"]
        for lib in libs:
            head += [f"{lib} ns/call", f"{lib} p50 / p99 / p99.9 / max ns"]
        if len(libs) == 2:
            head.append("ratio (range)")
        if markdown:
            print("| " + " | ".join(head) + " |")
            print("|" + "|".join(" --- " if i < 4 else " ---: " for i in range(len(head))) + "|")
        else:
            print("  ".join(head))
        for case, per in cases.items():
            call, speed, mode, threads = case.split()
            cells = [call, speed, mode, threads]
            medians = {}
            for lib in libs:
                runs = per.get(lib, [])
                if not runs:
                    cells += ["-", "-"]
                    continue
                med, lo, hi = fig(runs, "ns")
                medians[lib] = med
                cells.append(f"{med:.1f} ({lo:.1f}-{hi:.1f})")
                q = [fig(runs, k)[0] for k in ("p50", "p99", "p999", "max")]
                cells.append(" / ".join(f"{v:.0f}" for v in q))
            if len(libs) == 2 and len(medians) == 2:
                other = {r["run"]: r["ns"] for r in per[libs[1]]}
                ratios = [other[r["run"]] / r["ns"] for r in per[libs[0]] if r["run"] in other]
                cells.append(f"{statistics.median(ratios):.2f} ({min(ratios):.2f}-{max(ratios):.2f})")
            print(("| " + " | ".join(cells) + " |") if markdown else "  ".join(cells))


if __name__ == "__main__":
    main(sys.argv[1])
