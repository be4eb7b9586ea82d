#!/usr/bin/env python3
"""Opens the audit's HTML report in headless Chromium as a user would.
usage: report_browser_test.py REPORT_HTML SCREENSHOT_PNG
Fails on: a page that does not load, any console message, an image that did not decode, a
blank or nearly blank screenshot."""
import os
import re
import shutil
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.image  # noqa: E402

report, shot = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
browser = shutil.which("chromium") or shutil.which("chromium-browser")
if not browser:
    sys.exit("chromium not found (the set-up installs Debian's chromium)")
flags = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync", "--hide-scrollbars",
         "--enable-logging=stderr", "--v=0"]
failures = []
with tempfile.TemporaryDirectory() as profile:
    r = subprocess.run([browser, *flags, f"--user-data-dir={profile}", "--virtual-time-budget=10000", "--dump-dom",
                        "file://" + report], capture_output=True, text=True, timeout=180)
    dom, log = r.stdout, r.stderr
    r2 = subprocess.run([browser, *flags, f"--user-data-dir={profile}", "--window-size=1300,3000",
                         f"--screenshot={shot}", "file://" + report], capture_output=True, text=True, timeout=180)
    log += r2.stderr

console = [line for line in log.splitlines() if ":CONSOLE" in line]
if console:
    failures.append("console messages: " + " | ".join(console[:5]))
m = re.search(r'data-images="(\d+)"', dom)
b = re.search(r'data-images-broken="(\d+)"', dom)
if not m or not b:
    failures.append("the page's load handler did not run (no data-images attribute in the DOM)")
else:
    images, broken = int(m.group(1)), int(b.group(1))
    print(f"[cases] report in chromium: {images} images, {broken} broken")
    if images == 0 or broken:
        failures.append(f"{broken} of {images} images did not load")
if "robustness audit" not in dom:
    failures.append("the page has no title text")
if not os.path.exists(shot):
    failures.append("no screenshot written")
else:
    px = matplotlib.image.imread(shot)[:, :, :3]
    ink = (px.min(axis=2) < 0.8).mean()  # share of pixels that are not (nearly) white
    colours = len({tuple((p * 15).astype(int)) for p in px[::7, ::7].reshape(-1, 3)})
    print(f"[cases] report screenshot: {px.shape[1]}x{px.shape[0]}, {100 * ink:.1f}% ink, {colours} colour bins")
    if ink < 0.02 or colours < 8:
        failures.append(f"the screenshot looks blank ({100 * ink:.2f}% ink, {colours} colours)")
for f in failures:
    print("FAILED:", f)
sys.exit(1 if failures else 0)
