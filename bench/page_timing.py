"""How long the web page takes to open a road or a map in headless Chromium, in real time
(a screenshot's virtual time would not count the work): the page is driven over the
DevTools protocol through a pipe, and the page's own #timing (fetched, read, drawn) is
read once it is written.

usage: python3 page_timing.py URL [TIMEOUT_S]
prints the #timing text
"""

import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

url = sys.argv[1]
timeout = float(sys.argv[2]) if len(sys.argv) > 2 else 120.0
profile = tempfile.mkdtemp()
to_browser_r, to_browser_w = os.pipe()
from_browser_r, from_browser_w = os.pipe()
browser = subprocess.Popen(
    ["chromium", "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
     "--no-first-run", f"--user-data-dir={profile}", "--remote-debugging-pipe", "about:blank"],
    pass_fds=(3, 4), stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
    stderr=subprocess.DEVNULL,
    preexec_fn=lambda: (os.dup2(to_browser_r, 3), os.dup2(from_browser_w, 4)))
os.close(to_browser_r)
os.close(from_browser_w)
buffer, counter = b"", 0


def send(method, params=None, session=None):
    global counter
    counter += 1
    message = {"id": counter, "method": method, "params": params or {}}
    if session:
        message["sessionId"] = session
    os.write(to_browser_w, json.dumps(message).encode() + b"\0")
    return counter


def reply(wanted):
    global buffer
    while True:
        while b"\0" in buffer:
            raw, buffer = buffer.split(b"\0", 1)
            message = json.loads(raw)
            if message.get("id") == wanted:
                return message
        buffer += os.read(from_browser_r, 1 << 16)


try:
    target = reply(send("Target.createTarget", {"url": url}))["result"]["targetId"]
    session = reply(send("Target.attachToTarget", {"targetId": target, "flatten": True}))["result"]["sessionId"]
    started, text = time.time(), ""
    while time.time() - started < timeout:
        answer = reply(send("Runtime.evaluate", {"expression": "(document.getElementById('timing') || {}).textContent || (document.getElementById('error') || {}).textContent || ''", "returnByValue": True}, session))
        text = answer.get("result", {}).get("result", {}).get("value", "")
        if text:
            break
        time.sleep(0.1)
    print(text)
finally:
    browser.kill()
    shutil.rmtree(profile, ignore_errors=True)
