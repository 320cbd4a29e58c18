"""Issue 16 item 9: `hooke simulate` killed with SIGKILL at any moment (while stepping, while writing frames, inside
the commit) leaves its output folder holding either the previous complete series or the new complete one.

A complete series: simulation.pvd parses, names only frames that exist and are whole VTU files, and has the frame
count of one of the two runs. Kill times are spread over the run's measured duration, with extra weight on its end,
where the commit happens.
Usage: kill_simulate.py HOOKE MESH OUT [KILLS]
"""
import os
import random
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

hooke, mesh, out = sys.argv[1:4]
kills = int(sys.argv[4]) if len(sys.argv) > 4 else 30
folder = os.path.join(out, "sim")


def run(steps):
    return [hooke, "simulate", mesh, "--young", "14630", "--poisson", "0.25", "--integrator", "symplectic-euler",
            "--dt", "1e-5", "--steps", str(steps), "--every", "1", "--gravity", "-o", folder]


def frames_in_folder():
    """The frame count of the complete series in `folder`; fails the test when it is not complete."""
    pvd = os.path.join(folder, "simulation.pvd")
    if not os.path.exists(pvd):
        sys.exit(f"FAIL: {pvd} is missing")
    files = [d.get("file") for d in ET.parse(pvd).getroot().iter("DataSet")]
    for f in files:
        path = os.path.join(folder, f)
        if not os.path.exists(path):
            sys.exit(f"FAIL: {pvd} names {f}, which is missing")
        with open(path, "rb") as fh:
            if not fh.read().rstrip().endswith(b"</VTKFile>"):
                sys.exit(f"FAIL: {f} is not a whole VTU file")
    return len(files)


os.makedirs(out, exist_ok=True)
subprocess.run(run(40), check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)  # the previous output
old = frames_in_folder()
t0 = time.monotonic()
subprocess.run(run(80), check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
duration = time.monotonic() - t0
new = frames_in_folder()
subprocess.run(run(40), check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
print(f"a complete run takes {duration:.3f} s; series of {old} and {new} frames")
rng = random.Random(16)
seen = {old: 0, new: 0}
for k in range(kills):
    # Half the kills anywhere in the run, half in its last fifth (frames renamed, .pvd written, old frames removed).
    at = duration * (rng.uniform(0.0, 1.1) if k % 2 == 0 else rng.uniform(0.8, 1.05))
    p = subprocess.Popen(run(80), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(at)
    p.send_signal(signal.SIGKILL)
    p.wait()
    n = frames_in_folder()
    if n not in seen:
        sys.exit(f"FAIL: after a kill at {at:.3f} s the series has {n} frames, neither {old} nor {new}")
    seen[n] += 1
    if n == new:  # back to the old output for the next kill
        subprocess.run(run(40), check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
print(f"{kills} kills: the old series {seen[old]} times, the new one {seen[new]} times, never a mixture")
