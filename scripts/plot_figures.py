#!/usr/bin/python3
"""Draws the figure specs that hooke writes (JSON, see src/hooke/experiments/figure.hpp) as PNG files.

Usage: plot_figures.py SPEC.json [SPEC.json ...]
Each SPEC.json becomes SPEC.png beside it, written to a temporary file first and renamed. Deformation panels
are drawn in cm (spring model red over FEM black, as in Lloyd et al. 2007); curve panels as given.
Exit status 0 on success, 2 on a bad spec, 1 when matplotlib is missing.
"""
import json
import os
import sys

os.environ.setdefault("MPLBACKEND", "Agg")
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection
except ImportError as err:  # pragma: no cover - depends on the machine
    sys.stderr.write(f"plot_figures: matplotlib is not available ({err}); install python3-matplotlib\n")
    sys.exit(1)


def draw_deformation(ax, panel):
    h, v = panel["axes"]
    for d in panel["drawings"]:
        pos = d["positions"]
        segments = [[(100.0 * pos[i][h], 100.0 * pos[i][v]), (100.0 * pos[j][h], 100.0 * pos[j][v])]
                    for i, j in d["edges"]]
        ax.add_collection(LineCollection(segments, colors=d["color"], linewidths=d["line_width"],
                                         label=d["label"]))
    ax.autoscale()
    ax.set_aspect("equal")
    names = "xyz"
    ax.set_xlabel(f"{names[h]} (cm)")
    ax.set_ylabel(f"{names[v]} (cm)")


def draw_curves(ax, panel):
    for s in panel["series"]:
        ax.plot(s["x"], s["y"], s["style"], label=s["label"], markersize=4)
    ax.set_xlabel(panel["xlabel"])
    ax.set_ylabel(panel["ylabel"])
    ax.grid(True, linewidth=0.3)


def draw(spec_path):
    with open(spec_path, encoding="utf-8") as f:
        spec = json.load(f)
    panels = spec["panels"]
    fig, axes = plt.subplots(1, len(panels), figsize=(4.2 * len(panels), 4.2), squeeze=False)
    for ax, panel in zip(axes[0], panels):
        if panel["type"] == "deformation":
            draw_deformation(ax, panel)
        elif panel["type"] == "curves":
            draw_curves(ax, panel)
        else:
            raise ValueError(f"unknown panel type {panel['type']!r}")
        ax.set_title(panel["title"], fontsize=9)
        ax.legend(fontsize=7, loc="best")
    if spec.get("title"):
        fig.suptitle(spec["title"], fontsize=10)
    fig.tight_layout()
    out = os.path.splitext(spec_path)[0] + ".png"
    tmp = out + ".tmp.png"
    fig.savefig(tmp, dpi=110)
    plt.close(fig)
    os.replace(tmp, out)
    return out


def main(argv):
    if len(argv) < 2:
        sys.stderr.write(__doc__)
        return 2
    for path in argv[1:]:
        try:
            print(f"wrote {draw(path)}")
        except (OSError, ValueError, KeyError, IndexError, TypeError) as err:
            sys.stderr.write(f"plot_figures: {path}: {err}\n")
            return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
