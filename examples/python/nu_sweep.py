"""A nu sweep in a few lines: calibrate the cylinder with a hole for Poisson's ratios 0 ... 0.49 by two methods,
compare each with the linear FEM under stretch at 0.1 % strain, and plot the relative L2 error against nu.

Usage: PYTHONPATH=build/release/python /usr/bin/python3 examples/python/nu_sweep.py [OUT_DIR]
Writes OUT_DIR/nu_sweep.png and nu_sweep.csv (default out/nu_sweep).
"""
import os
import pathlib
import sys
import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import hooke  # noqa: E402

out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/nu_sweep")
out.mkdir(parents=True, exist_ok=True)
meshes = pathlib.Path(os.environ.get("HOOKE_MESH_DATA", pathlib.Path(__file__).resolve().parents[2] / "data" / "meshes"))
mesh = hooke.read_mesh(meshes / "cylinder_hole.msh")

nus = [0.0, 0.1, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.49]
rows = []
for method in ("lloyd-tet", "stiffness-fit"):
    for nu in nus:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", hooke.ValidityWarning)  # lloyd-tet away from nu = 1/4, as expected
            model = hooke.calibrate(mesh, hooke.Material(14630.0, nu), method)
        c = hooke.compare(model, "stretch", strain=0.001)
        rows.append((method, nu, c.relative_l2, c.max_error))
        print(f"{method:14s} nu {nu:4.2f}: relative L2 {c.relative_l2:.3f}, max {1e3 * c.max_error:.4f} mm")

with open(out / "nu_sweep.csv", "w") as f:
    f.write("method,nu,relative_l2,max_error_m\n")
    for r in rows:
        f.write(f"{r[0]},{r[1]},{r[2]:.6g},{r[3]:.6g}\n")
fig, ax = plt.subplots(figsize=(5, 3.5))
for method in ("lloyd-tet", "stiffness-fit"):
    ax.plot([r[1] for r in rows if r[0] == method], [r[2] for r in rows if r[0] == method], "o-", label=method)
ax.set_xlabel("Poisson's ratio ν")
ax.set_ylabel("relative L2 node error vs linear FEM")
ax.set_title("cylinder_hole.msh, stretch at 0.1 % strain")
ax.legend()
fig.tight_layout()
fig.savefig(out / "nu_sweep.png", dpi=120)
print(f"wrote {out / 'nu_sweep.png'} and {out / 'nu_sweep.csv'}")
