#!/usr/bin/env python3
"""Physics and draw rates of the viewer under Xvfb (issue: the haptic loop must keep 1 kHz).

Runs `hooke view` on the benchmark cylinders (1 089 and 11 425 nodes, as experiments::benchmark_cylinder: r 1 cm,
h 2 cm, lloyd-tet, E 14 630 Pa, nu 0.25, gravity, Rayleigh alpha 40 1/s) with a scripted grab-and-drag for
--seconds of simulated time (a tenth of it on the 11k cylinder, whose implicit steps take far longer than dt), and prints the viewer's own numbers (--stats): steps per second of wall time, the
median and p99 step time, the draw rate. A benchmark, not a test: the figures go into notes and docs, not asserts.

Usage: PYTHONPATH=build/release/python bench/viewer_rate.py HOOKE [--sizes 1k,10k] [--integrators local-global,...]
       [--seconds 5] [--out DIR]
"""
import argparse
import json
import os
import subprocess
import tempfile

import hooke

SIZES = {"1k": (12, 8), "10k": (24, 24)}  # mesh::tet_cylinder n, layers (experiments::benchmark_cylinder)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("hooke")
    p.add_argument("--sizes", default="1k,10k")
    p.add_argument("--integrators", default="local-global,implicit-euler")
    p.add_argument("--seconds", type=float, default=5.0, help="simulated seconds on 1k (a tenth of it on 10k)")
    p.add_argument("--global-solve", default="chebyshev", help="local-global: direct or chebyshev")
    p.add_argument("--out", default=tempfile.mkdtemp(prefix="viewer_rate_"))
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for size in a.sizes.split(","):
        n, layers = SIZES[size]
        mesh_path = os.path.join(a.out, f"cylinder_{size}.vtu")
        hooke.write_mesh(mesh_path, hooke.tet_cylinder(0.01, 0.02, n, layers))
        for integrator in a.integrators.split(","):
            t = a.seconds if size == "1k" else a.seconds / 10
            script = os.path.join(a.out, "drag.txt")
            with open(script, "w") as f:
                f.write(f"0 grab-nearest 0 0 0.02\n0.01 drag 0.002 0 0 over {t / 2}\n{t} quit\n")
            stats = os.path.join(a.out, f"stats_{size}_{integrator}.json")
            cmd = ["xvfb-run", "-a", "-s", "-screen 0 1024x768x24", a.hooke, "view", mesh_path, "--young", "14630",
                   "--poisson", "0.25", "--method", "lloyd-tet", "--gravity", "--damping-mass", "40", "--integrator",
                   integrator, "--global-solve", a.global_solve, "--script", script, "--stats", stats]
            r = subprocess.run(cmd, capture_output=True, text=True)
            if r.returncode != 0:
                print(f"{size} {integrator}: failed ({r.returncode}): {r.stderr.strip()}")
                continue
            s = json.load(open(stats))
            rows.append((int(s["nodes"]), integrator + (f" ({a.global_solve})" if integrator == "local-global" else ""), s))
    print("| nodes | integrator | physics steps/s of wall time | step ms median | step ms p99 | steps longer than dt "
          "| draw fps |")
    print("|---|---|---|---|---|---|---|")
    for nodes, integrator, s in rows:
        print(f"| {nodes} | {integrator} | {s['steps_per_wall_second']:.0f} | {s['step_ms_median']:.3f} | "
              f"{s['step_ms_p99']:.3f} | {s['overruns']} of {s['steps']} | {s['draw_rate_hz']:.0f} |")


if __name__ == "__main__":
    main()
