"""The cost of stepping from Python against stepping in C++ (issue: at most 10 % on the 11k-node cylinder).

Runs local-global (Chebyshev, the haptic-rate integrator) and implicit-euler-linearised (cg) on the benchmark
cylinders of `hooke bench` (1 089 and 11 425 nodes), alternating batches of 10 steps called one by one from Python
with batches of 10 steps run by Simulator.run in C++, and prints the medians and their ratio. Exit code 1 when a
ratio on the 11k cylinder exceeds 1.10.
Usage: PYTHONPATH=build/release/python /usr/bin/python3 bench/bench_python_step.py [batches]
"""
import statistics
import sys
import time

import warnings

import hooke

warnings.simplefilter("ignore", hooke.ValidityWarning)


def measure(size, integrator, batches, **options):
    n, layers = size
    mesh = hooke.tet_cylinder(0.01, 0.02, n, layers)
    model = hooke.calibrate(mesh, hooke.Material(14630.0, 0.25), "lloyd-tet")
    problem = hooke.Problem(model)
    problem.apply_load("stretch", traction=0.0)  # clamps the bottom
    sim = hooke.Simulator(problem, integrator, gravity=[0.0, 0.0, -9.81], **options)
    sim.step(1e-3)
    python_ms, cpp_ms = [], []
    for _ in range(batches):
        for _ in range(10):
            t0 = time.perf_counter()
            sim.step(1e-3)
            python_ms.append(1e3 * (time.perf_counter() - t0))
        cpp_ms += sim.run(10, 1e-3)
    p, c = statistics.median(python_ms), statistics.median(cpp_ms)
    print(f"{mesh.node_count} nodes, {integrator} {options}: Python {p:.3f} ms/step, C++ {c:.3f} ms/step, "
          f"ratio {p / c:.3f}")
    return p / c


if __name__ == "__main__":
    batches = int(sys.argv[1]) if len(sys.argv) > 1 else 10
    worst = 0.0
    for size in ((12, 8), (24, 24)):
        ratios = [measure(size, "local-global", batches, global_solve="chebyshev"),
                  measure(size, "implicit-euler-linearised", batches, linear_solver="cg", cg_tolerance=1e-2)]
        if size == (24, 24):
            worst = max(ratios)
    sys.exit(0 if worst <= 1.10 else 1)
