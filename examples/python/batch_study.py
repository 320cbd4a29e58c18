"""A study on a local Dask cluster: three committed meshes x three Poisson's ratios x two methods, each model
calibrated and certified against the linear FEM (stretch, compress, shear at 1 % strain), the results table written
as the jobs finish, and a plot of the worst relative L2 error against nu per method and mesh. Run it twice: the second
run finds every result in the table and runs nothing.

Usage: PYTHONPATH=build/release/python /usr/bin/python3 examples/python/batch_study.py [OUT_DIR] [SCHEDULER]
Writes OUT_DIR/results.csv, OUT_DIR/models/*.json and OUT_DIR/batch_study.png (default out/batch_study);
SCHEDULER: a Dask scheduler's address (tcp://host:8786) instead of the local cluster.
"""
import os
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from hooke import batch  # noqa: E402


def main():
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/batch_study")
    scheduler = sys.argv[2] if len(sys.argv) > 2 else None
    meshes = pathlib.Path(os.environ.get("HOOKE_MESH_DATA",
                                         pathlib.Path(__file__).resolve().parents[2] / "data" / "meshes"))
    jobs = [{"mesh": str(meshes / f"{mesh}.msh"), "young": 14630.0, "poisson": nu, "method": method,
             "name": f"{mesh}-{method}-{nu}"}
            for mesh in ("cylinder", "cylinder_hole", "cone")
            for nu in (0.3, 0.45, 0.49)
            for method in ("any-nu-tet", "stiffness-fit-volume")]
    results = batch.run(jobs, out, client=scheduler)  # a local cluster of one worker per core unless told
    print(results[["name", "status", "worst_relative_l2", "seconds", "peak_memory_mb"]].to_string(index=False))

    fig, axes = plt.subplots(1, 3, figsize=(11, 3.4), sharey=True)
    for ax, mesh in zip(axes, ("cylinder", "cylinder_hole", "cone")):
        for method, style in (("any-nu-tet", "o-"), ("stiffness-fit-volume", "s-")):
            r = results[(results["method"] == method) & results["mesh"].str.endswith(f"/{mesh}.msh")]
            r = r.sort_values("poisson")
            ax.plot(r["poisson"], r["worst_relative_l2"], style, label=method)
        ax.set_title(f"{mesh}.msh")
        ax.set_xlabel("Poisson's ratio ν")
    axes[0].set_ylabel("worst relative L2 vs linear FEM")
    axes[0].legend()
    fig.tight_layout()
    fig.savefig(out / "batch_study.png", dpi=120)
    failed = int((results["status"] != "ok").sum())
    print(f"wrote {out / 'results.csv'} ({len(results)} jobs, {failed} failed) and {out / 'batch_study.png'}")
    return 0 if failed == 0 else 1


if __name__ == "__main__":  # Dask's worker processes import this file: the study runs only here
    sys.exit(main())
