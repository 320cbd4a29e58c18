#!/usr/bin/env python3
"""The study behind docs/methods/any_nu.md, "Why the fitted springs are too compliant": one global stiffness factor c
fitted in closed form to one FEM load case (Lloyd Eq. 1 with theta = c), evaluated on the other (held out).
Usage: PYTHONPATH=build/release/python /usr/bin/python3 scripts/stiffness_scale_study.py"""
import os

import hooke
import numpy as np

MESHES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "meshes")
E = 14630.0
for mesh_name in ["cone", "cylinder_hole"]:
    mesh = hooke.read_mesh(os.path.join(MESHES, mesh_name + ".msh"))
    X = np.asarray(mesh.points)
    for nu in [0.0, 0.25, 0.3, 0.45, 0.49]:
        row = []
        for name in ["lloyd-tet", "stiffness-fit"]:
            m = hooke.calibrate(mesh, hooke.Material(E, nu), name)
            cs = {l: hooke.compare(m, l, strain=0.001) for l in ["stretch", "shear"]}
            us = {l: np.asarray(c.model_positions) - X for l, c in cs.items()}
            uf = {l: np.asarray(c.fem_positions) - X for l, c in cs.items()}
            t = sum((us[l] * uf[l]).sum() for l in us) / sum((us[l] ** 2).sum() for l in us)
            # held out: fit on one load, evaluate the other
            ho = {}
            for fit, ev in [("stretch", "shear"), ("shear", "stretch")]:
                tf = (us[fit] * uf[fit]).sum() / (us[fit] ** 2).sum()
                ho[ev] = np.linalg.norm(tf * us[ev] - uf[ev]) / np.linalg.norm(uf[ev])
            row.append(f"{name}: stretch {cs['stretch'].relative_l2:.3f} shear {cs['shear'].relative_l2:.3f} | c={1/t:.3f} held-out stretch {ho['stretch']:.3f} shear {ho['shear']:.3f}")
        print(f"{mesh_name} nu={nu}: " + " || ".join(row), flush=True)
