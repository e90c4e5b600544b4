"""Checks the point `opencrg odr view`'s page reads (headless Chromium's DOM of the page
opened with #probe, in test.sh) against `opencrg odr eval` at the same x/y: the road and
the friction equal, the height, s and t within the 1 mm the page shows plus the mesh's
bound.

usage: python3 check_odr_view.py DOM.html MAP OPENCRG [BOUND]
"""

import re
import subprocess
import sys

dom, map_path, opencrg = sys.argv[1:4]
bound = float(sys.argv[4]) if len(sys.argv) > 4 else 0.005
text = re.search(r'<div id="pick">([^<]*)</div>', open(dom).read()).group(1)
read = dict(re.findall(r"(\w+) (-?[\w.]+)", text))
print(f"the page reads: {text}")
for name in ("x", "y", "z", "road", "lane", "s", "t", "friction"):
    assert name in read, f"{name} missing from {text!r}"
out = subprocess.run([opencrg, "odr", "eval", map_path], input=f"{read['x']} {read['y']}\n", capture_output=True,
                     text=True, check=True).stdout.split()
z, friction, road, s, t = float(out[0]), out[1], out[2], float(out[3]), float(out[4])
assert road == read["road"], (road, read["road"])
assert abs(float(friction) - float(read["friction"])) < 1e-3, (friction, read["friction"])
assert abs(z - float(read["z"])) <= bound + 0.001, (z, read["z"])
assert abs(s - float(read["s"])) <= 0.002 and abs(t - float(read["t"])) <= 0.002, (s, t, read)
print(f"odr eval agrees: z {z:.4f}, road {road}, s {s:.3f}, t {t:.3f}, friction {friction}")
