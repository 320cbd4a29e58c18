#!/usr/bin/env python3
"""Writes tests/data/identify/nnls_scipy.txt: a 40 x 30 non-negative least-squares problem with columns over four
decades and scipy.optimize.nnls's answer, the independent solver tests/identify/test_bounded_least_squares.cpp checks
hooke's against. Run with Debian's /usr/bin/python3 (python3-scipy)."""
import pathlib

import numpy as np
from scipy.optimize import nnls

rng = np.random.default_rng(2007)
rows, cols = 40, 30
a = rng.normal(size=(rows, cols)) * (rng.random((rows, cols)) < 0.4)
a *= 10.0 ** (np.arange(cols) % 4 - 2)
b = rng.normal(size=rows)
x, _ = nnls(a, b, maxiter=10000)
out = pathlib.Path(__file__).resolve().parent.parent / "tests" / "data" / "identify" / "nnls_scipy.txt"
with open(out, "w") as f:
    f.write(f"{rows} {cols}\n")
    for r in range(rows):
        f.write(" ".join(repr(float(v)) for v in a[r]) + "\n")
    f.write(" ".join(repr(float(v)) for v in b) + "\n")
    f.write(" ".join(repr(float(v)) for v in x) + "\n")
print(f"wrote {out}: {int((x == 0).sum())} of {cols} at zero, residual {np.linalg.norm(a @ x - b):.6g}")
