#!/usr/bin/env python3
"""Runs a command and prints how long it took and the most private memory it held: the
peak of RssAnon in /proc/PID/status (Linux), sampled every 5 ms, and its peak resident
size (VmHWM, file pages included).

usage: peak_private.py COMMAND [ARG ...]   (the command's own output passes through)
Prints to stderr: "wall S rss_anon_peak KIB hwm KIB status N".
"""
import subprocess
import sys
import time


def figure(pid, key):
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith(key + ":"):
                    return int(line.split()[1])
    except (FileNotFoundError, ProcessLookupError, ValueError):
        pass
    return 0


def main(argv):
    start = time.monotonic()
    proc = subprocess.Popen(argv)
    peak = hwm = 0
    while proc.poll() is None:
        peak = max(peak, figure(proc.pid, "RssAnon"))
        hwm = max(hwm, figure(proc.pid, "VmHWM"))
        time.sleep(0.005)
    wall = time.monotonic() - start
    print(f"wall {wall:.2f} rss_anon_peak {peak} hwm {hwm} status {proc.returncode}", file=sys.stderr)
    return proc.returncode


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
