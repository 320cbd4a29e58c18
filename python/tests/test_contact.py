"""Rigid tools from Python: Problem.add_tool, hooke.press and Simulator.move_tool (docs/contact.md)."""
import numpy as np
import pytest

import hooke


def pressed_problem(friction=0.0):
    mesh = hooke.tet_cylinder(0.01, 0.02, 6, 4)
    model = hooke.calibrate(mesh, hooke.Material(14630.0, 0.45), method="any-nu-tet")
    problem = hooke.Problem(model)
    x = mesh.points
    problem.fix_nodes(np.flatnonzero(x[:, 2] < x[:, 2].min() + 1e-9).tolist())
    top = x[:, 2].max()
    tool = problem.add_tool("sphere:0.005", [0.0, 0.0, top + 0.0055], friction=friction)
    return problem, tool, top


def test_a_static_press_pushes_back_harder_the_deeper_and_nothing_enters_the_tool():
    problem, tool, top = pressed_problem()
    assert tool.shape == "sphere:0.005" and tool.contact_distance > 0.0
    depths = [1e-3, 2e-3, 3e-3]  # the 6-sector mesh has no node within the contact patch of a shallower press
    steps = hooke.press(problem, tool, [[0.0, 0.0, top + 0.005 - d] for d in depths])
    forces = [s["force"][2] for s in steps]
    assert 0.0 < forces[0] < forces[1] < forces[2]
    assert all(0.0 < s["smallest_gap"] < tool.contact_distance and s["active"] > 0 for s in steps)
    # the tool's own evaluation at the last equilibrium is the press's force
    assert np.allclose(tool.force(steps[-1]["positions"]), steps[-1]["force"])
    assert abs(np.asarray(steps[-1]["force"][:2])).max() < 0.05 * forces[-1]  # centred: mostly vertical


def test_a_simulator_moves_the_tool_and_the_body_stays_outside():
    problem, tool, top = pressed_problem()
    sim = hooke.Simulator(problem, "implicit-euler", damping_mass=40.0)
    for k in range(1, 41):
        depth = -0.5e-3 + 2.5e-3 * min(k / 20, 1.0)  # from 0.5 mm above the top to 2 mm deep, then held
        sim.move_tool(tool, [0.0, 0.0, top + 0.005 - depth])
        sim.step(2e-3)
        assert tool.smallest_gap(sim.positions) > 0.0
    assert tool.force(sim.positions)[2] > 0.0


def test_tools_are_refused_when_malformed():
    problem, tool, top = pressed_problem()
    with pytest.raises(hooke.InvalidArgument, match="tool 'cube:1'"):
        problem.add_tool("cube:1", [0.0, 0.0, 1.0])
    with pytest.raises(hooke.InvalidArgument, match="rotation"):
        tool.set_pose([0.0, 0.0, 1.0], 2.0 * np.eye(3))
    with pytest.raises(ValueError, match="position"):
        tool.set_pose([0.0, np.nan, 1.0])


def test_friction_drags_the_surface_along_with_a_sliding_tool():
    """A sphere pressed 2 mm and then slid 1 mm sideways (static poses): with friction the body holds it back harder
    than without, and its surface nodes follow the tool further."""
    lateral = {}
    for mu in (0.0, 0.5):
        problem, tool, top = pressed_problem(mu)
        poses = [[0.0, 0.0, top + 0.005 - d] for d in (1e-3, 2e-3)] + [[s, 0.0, top + 0.003] for s in (5e-4, 1e-3)]
        steps = hooke.press(problem, tool, poses)
        lateral[mu] = steps[-1]["force"][0]
        assert steps[-1]["smallest_gap"] > 0.0
    assert lateral[0.5] < -1.5 * abs(lateral[0.0])  # the body drags on the tool against its motion (+x)
    with pytest.raises(hooke.InvalidArgument, match="friction"):
        pressed_problem(-1.0)


def test_compare_under_contact_presses_the_model_and_the_fem_alike():
    """A sphere pressed 1 mm into the small cylinder, any-nu-tet against the neo-Hookean FEM: both push back, the
    forces agree within the model's error, and the field's error is reported."""
    mesh = hooke.tet_cylinder(0.01, 0.02, 6, 4)
    model = hooke.calibrate(mesh, hooke.Material(14630.0, 0.45), method="any-nu-tet")
    top = mesh.points[:, 2].max()
    rows = hooke.compare_under_contact(model, "sphere:0.005", [0.0, 0.0, top + 0.005], 2e-3, steps=2)
    assert len(rows) == 2 and rows[-1]["travel"] == pytest.approx(2e-3)
    for r in rows:
        assert r["fem_force"][2] > 0.0 and r["model_force"][2] > 0.0 and r["smallest_gap"] > 0.0
        assert 0.0 <= r["force_error"] < 0.3 and r["relative_l2"] > 0.0
    with pytest.raises(hooke.InvalidArgument, match="depth"):
        hooke.compare_under_contact(model, "sphere:0.005", [0.0, 0.0, top + 0.005], 0.0)
