#!/usr/bin/env python3
"""Fails when a file in src/hooke/<layer>/ includes a header of a layer above it (the layer order of docs/architecture.md)."""
import pathlib
import re
import sys

ORDER = ["core", "mesh", "io", "image", "material", "model", "fem", "springs", "surface", "contact", "calibrate", "solve", "identify", "experiments", "interactive"]
# calibrate sits below solve: its solves are linear (core's SparseCholesky), and solve::simulate builds models by name.
# fem, springs and surface are siblings: none may include another.
SIBLINGS = {"fem", "springs", "surface", "contact"}

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".") / "src" / "hooke"
bad = []
for path in sorted(root.rglob("*.[ch]pp")):
    layer = path.relative_to(root).parts[0]
    if layer not in ORDER:
        bad.append(f"{path}: folder '{layer}' is not a layer of docs/architecture.md")
        continue
    for n, line in enumerate(path.read_text().splitlines(), 1):
        m = re.match(r'\s*#include\s*<hooke/([a-z_]+)/', line)
        if not m:
            continue
        target = m.group(1)
        if target not in ORDER:
            bad.append(f"{path}:{n}: includes unknown layer '{target}'")
        elif ORDER.index(target) > ORDER.index(layer) or (
                target != layer and target in SIBLINGS and layer in SIBLINGS):
            bad.append(f"{path}:{n}: layer '{layer}' includes '{target}', which is above it")
print("\n".join(bad) if bad else f"layer order respected in {len(list(root.rglob('*.[ch]pp')))} files")
sys.exit(1 if bad else 0)
