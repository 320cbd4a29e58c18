"""Issue 16 item 9: `hooke reproduce` killed with SIGKILL at any moment leaves the previous complete report: the
report (.md) whole, every figure it links present (as its spec, figures/NAME.json, with --no-figures), the .json
parsable, and no report of the killed run. Before the fix the report was written before its figures, so a kill
left a report linking missing figures.

Kills land in the last 15 % of a measured run, where the report and figures are moved into place.
Usage: kill_reproduce.py HOOKE OUT [KILLS]
"""
import json
import os
import random
import re
import signal
import subprocess
import sys
import time

hooke, out = sys.argv[1:3]
kills = int(sys.argv[3]) if len(sys.argv) > 3 else 3
folder = os.path.join(out, "arnab2008")
command = [hooke, "reproduce", "arnab2008", "--no-figures", "-o", folder]


def check():
    md = os.path.join(folder, "arnab2008.md")
    if not os.path.exists(md):
        sys.exit(f"FAIL: {md} is missing")
    text = open(md).read()
    if not text.rstrip().endswith(")"):  # the report ends with its last figure link
        sys.exit("FAIL: the report is cut short")
    for link in re.findall(r"\(figures/([a-z0-9_]+)\.png\)", text):
        if not os.path.exists(os.path.join(folder, "figures", link + ".json")):
            sys.exit(f"FAIL: the report links {link}, whose figure is missing")
    json.load(open(os.path.join(folder, "arnab2008.json")))
    return text


t0 = time.monotonic()
subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
duration = time.monotonic() - t0
check()
rng = random.Random(9)
for k in range(kills):
    at = duration * rng.uniform(0.85, 1.02)
    p = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(at)
    p.send_signal(signal.SIGKILL)
    p.wait()
    check()
    print(f"kill {k + 1} at {at:.2f} s of a {duration:.2f} s run: the report and its figures are whole")
