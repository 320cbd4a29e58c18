"""Statics and dynamics from Python: the same answers as the library, reports, SolverFailure, the probe."""
import numpy as np
import pytest

import hooke


def cylinder_problem(n=12, layers=4, nu=0.3):
    mesh = hooke.tet_cylinder(0.01, 0.02, n, layers)
    model = hooke.calibrate(mesh, hooke.Material(14630.0, nu), "lloyd-tet")
    return mesh, model


def test_static_equilibrium_agrees_with_linear_static_at_small_load():
    mesh, model = cylinder_problem()
    p = hooke.Problem(model)
    p.apply_load("stretch", strain=1e-5)
    x_lin, r_lin = hooke.linear_static(p)
    x, r = hooke.static_equilibrium(p)
    assert r.status == "converged" and r_lin.converged
    u = x - mesh.points
    assert np.abs(x - x_lin).max() < 1e-3 * np.abs(u).max()


def test_solver_failure_carries_the_report():
    mesh, model = cylinder_problem()
    p = hooke.Problem(model)  # nothing held: singular
    p.external_force = np.full(3 * mesh.node_count, 1e-3)
    with pytest.raises(hooke.SolverFailure) as e:
        hooke.static_equilibrium(p)
    assert e.value.report.status == "singular"
    x, report = hooke.static_equilibrium(p, raise_on_failure=False)
    assert report.status == "singular"
    with pytest.raises(ValueError, match="external_force"):
        p.external_force = np.zeros(5)


def test_simulator_views_and_probe():
    mesh, model = cylinder_problem()
    p = hooke.Problem(model)
    p.apply_load("stretch", traction=0.0)  # clamps the bottom
    sim = hooke.Simulator(p, "implicit-euler", gravity=[0.0, 0.0, -9.81])
    x = sim.positions
    assert x.shape == (mesh.node_count, 3) and not x.flags.writeable
    top = int(np.argmax(mesh.points[:, 2]))
    sim.grab([top])
    for k in range(10):
        sim.drive([0.0, 0.0, 1e-4 * (k + 1) / 10])
        r = sim.step(1e-3)
        assert r.converged and r.iterations > 0
    assert x[top, 2] == pytest.approx(mesh.points[top, 2] + 1e-4, abs=1e-12)  # the view follows the state
    assert sim.probe_force[2] < 0  # the body pulls the probe back
    sim.release()
    sim.step(1e-3)
    assert sim.probe_force == [0.0, 0.0, 0.0]


def test_simulator_settings_by_name():
    # The integrator's options by the names `hooke simulate` takes (solve::simulator_fields), dashes as underscores:
    # a Newton budget of one iteration leaves an implicit step short of its tolerance, the default converges.
    mesh, model = cylinder_problem()
    p = hooke.Problem(model)
    p.apply_load("stretch", traction=0.0)
    reports = {}
    for budget in (None, 1):
        extra = {} if budget is None else {"newton_iterations": budget, "newton_tolerance": 1e-12}
        sim = hooke.Simulator(p, "implicit-euler", gravity=[0.0, 0.0, -9.81], linear_solver="cg", **extra)
        reports[budget] = sim.step(1e-2)
    assert reports[None].converged
    assert not reports[1].converged and reports[1].iterations == 1
    with pytest.raises(TypeError, match="newton_iteration"):
        hooke.Simulator(p, "implicit-euler", newton_iteration=3)
    with pytest.raises(ValueError, match="integer"):
        hooke.Simulator(p, "implicit-euler", newton_iterations=2.5)


def test_docstrings_say_units():
    assert "Pa" in hooke.Material.__init__.__doc__
    assert "N/m" in hooke.calibrate.__doc__
    assert "m" in hooke.read_mesh.__doc__
