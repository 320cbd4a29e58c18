"""The finite-element reference from Python: hooke.fem.solve."""
from . import _hooke


def solve(mesh, material, load="stretch", strain=None, traction=None):
    """The FEM static answer of `mesh` under one of the papers' load cases.

    mesh      hooke.Mesh (m)
    material  hooke.Material; its law ('linear', 'stvk', 'neohookean') chooses the FEM model: 'linear' is one
              linear solve, the others Newton with load stepping and the stability check
    load      'stretch', 'compress' or 'shear' on the top face (the bottom clamped)
    strain    the mean top strain of the linear FEM, or
    traction  the traction on the top face, Pa

    Returns (positions (N, dim) in m, hooke.SolveReport); raises hooke.SolverFailure (with .report) unless it
    converged.
    """
    model = _hooke._calibrate(mesh, material, {"method": "fem"}, [])
    problem = _hooke.Problem(model)
    problem.apply_load(load, traction=traction, strain=strain)
    if material.law == "linear":
        return _hooke.linear_static(problem)
    return _hooke.static_equilibrium(problem)
