"""The web page in headless Chromium, served from WEB on loopback: `?road=...&probe=...`
for the demo road and the demo map (its CRG file fetched beside it) answers what the
native command answers (within 1e-9 m), a damaged road shows the command's message, the
roughness table holds the command's IRI, and the top view, the 3D view and the roughness
figure are drawn (screenshots: many pixels in the height colours; the tracks' colours on
a road's page, not on a map's).

usage: python3 test_page.py WEB OPENCRG EXAMPLES
"""

import functools
import http.server
import json
import math
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import threading

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "crates/opencrg-cli/tests"))
from check_view import pixels  # noqa: E402

web, opencrg, examples = map(pathlib.Path, sys.argv[1:4])
root = pathlib.Path(tempfile.mkdtemp())
shutil.copytree(web, root / "web")
(root / "data").mkdir()
for name in ("demo_road.crg", "demo_map.xodr"):
    shutil.copy(examples / name, root / "data" / name)
# A damaged road: the demo road cut short.
(root / "data" / "damaged.crg").write_bytes((examples / "demo_road.crg").read_bytes()[:1500])
class Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


handler = functools.partial(Quiet, directory=str(root))
server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
threading.Thread(target=server.serve_forever, daemon=True).start()
base = f"http://127.0.0.1:{server.server_address[1]}/web/index.html"


def chromium(url, *args, size="1400,800"):
    profile = tempfile.mkdtemp()
    out = subprocess.run(
        ["chromium", "--headless", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
         "--enable-unsafe-swiftshader", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run", f"--user-data-dir={profile}",
         f"--window-size={size}", "--virtual-time-budget=8000", *args, url],
        capture_output=True, text=True, timeout=120)
    shutil.rmtree(profile, ignore_errors=True)
    return out.stdout


dom = ""


def probe(query):
    global dom
    dom = chromium(f"{base}?{query}", "--dump-dom")
    error = re.search(r'id="error">([^<]*)<', dom)
    assert error is None or not error[1].strip(), f"the page says: {error[1]}"
    return re.search(r'id="probe">([^<]*)<', dom)[1].split()


def close(a, b):
    a, b = float(a), float(b)
    assert (math.isnan(a) and math.isnan(b)) or abs(a - b) <= 1e-9, (a, b)


# The road: z u v against `opencrg eval --xy` (x,y,u,v,z,...).
got = probe("road=../data/demo_road.crg&probe=50,3")
row = subprocess.run([str(opencrg), "eval", "--xy", str(examples / "demo_road.crg")], input="50 3\n",
                     capture_output=True, text=True, check=True).stdout.splitlines()[1].split(",")
for ours, theirs in zip(got, (row[4], row[2], row[3])):
    close(ours, theirs)
# Its roughness table: the IRI of the command's tracks.
table = re.search(r'id="roughness">([^<]*)<', dom)[1].splitlines()[1:]
iri = json.loads(subprocess.run([str(opencrg), "roughness", str(examples / "demo_road.crg"), "--json"],
                                capture_output=True, text=True, check=True).stdout)["tracks"]
assert [line.split()[1] for line in table] == [f"{t['iri']:.3f}" for t in iri], (table, iri)
# A damaged road: the page shows the command's message, and no road.
dom = chromium(f"{base}?road=../data/damaged.crg&probe=50,3", "--dump-dom")
error = re.search(r'id="error">([^<]*)<', dom)[1]
native = subprocess.run([str(opencrg), "info", str(root / "data" / "damaged.crg")], capture_output=True, text=True)
assert native.returncode != 0 and native.stderr.split(": ", 2)[2].strip() in error, (error, native.stderr)
assert "No road open." in dom and re.search(r'id="probe">([^<]*)<', dom)[1] == "", dom
# The map: z friction road s t against `opencrg odr eval`.
got = probe("road=../data/demo_map.xodr&probe=20,-2")
native = subprocess.run([str(opencrg), "odr", "eval", str(examples / "demo_map.xodr")], input="20 -2\n",
                        capture_output=True, text=True, check=True).stdout.split()
assert got[2] == native[2], (got, native)
for k in (0, 1, 3, 4):
    close(got[k], native[k])
# The top view and the 3D view (the command's viewer, in a frame) drawn: many pixels in
# the height colours (saturated).
shares = []
for query in ("road=../data/demo_map.xodr", "road=../data/demo_road.crg&view=3d"):
    shot = root / "page.png"
    chromium(f"{base}?{query}", f"--screenshot={shot}")
    rows = pixels(shot)
    coloured = sum(1 for r in rows for (R, G, B) in r if max(R, G, B) - min(R, G, B) > 60)
    total = sum(len(r) for r in rows)
    assert coloured > 0.02 * total, f"{query}: {coloured} of {total} pixels coloured"
    shares.append(f"{100 * coloured / total:.1f} %")
# The roughness figure: the tracks' lines in their colours on the road's page (the IRI
# steps hold runs of exactly those pixels; the outer tracks of the demo road nearly
# coincide, the last drawn covering the first), none on the map's.
track_colours = [(30, 90, 200), (200, 60, 40), (40, 150, 60)]
counts = {}
for query in ("road=../data/demo_road.crg", "road=../data/demo_map.xodr"):
    shot = root / "page.png"
    chromium(f"{base}?{query}", f"--screenshot={shot}", size="1400,2200")
    rows = pixels(shot)
    counts[query] = [sum(1 for r in rows for p in r if p == c) for c in track_colours]
road_counts, map_counts = counts.values()
assert all(n > 50 for n in road_counts) and sum(road_counts) > 1000 and all(n < 50 for n in map_counts), counts
print(f"web page: roughness figure drawn ({', '.join(map(str, road_counts))} pixels of the three tracks' colours)")
print(f"web page: road and map probes as the command answers, its roughness; top and 3D views drawn ({', '.join(shares)} coloured)")
server.shutdown()
shutil.rmtree(root, ignore_errors=True)
