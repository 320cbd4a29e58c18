"""hooke.LiveSimulation (the viewer's physics) from Python: a quasi-static drag feels the FEM's holding force, a
live change of nu recalibrates, bad settings raise with the facts."""
import time

import numpy as np
import pytest

import hooke


def cylinder_model(method="fem"):
    mesh = hooke.tet_cylinder(0.01, 0.02, 8, 5)
    return hooke.calibrate(mesh, hooke.Material(14630.0, 0.3), method)


def top_node(model):
    x = np.asarray(model.mesh.points)
    top = np.flatnonzero(np.isclose(x[:, 2], x[:, 2].max()))
    return int(top[np.argmin(np.linalg.norm(x[top, :2], axis=1))])


def test_quasi_static_drag_feels_the_fem_holding_force():
    model = cylinder_model("fem")
    sim = hooke.LiveSimulation(model, damping_mass=60.0)
    node = top_node(model)
    offset = np.array([1e-3, 0.0, -5e-4])
    sim.grab([node])
    for k in range(1, 1501):
        sim.drag(min(1.0, k / 300) * offset)
        sim.step()
    target = np.asarray(model.mesh.points)[node] + offset
    positions, held = hooke.fem_probe_equilibrium(model, "linear", sim.clamped_nodes, [node], target)
    felt = np.array(sim.probe_force)
    assert np.linalg.norm(felt - np.array(held)) < 0.01 * np.linalg.norm(held)
    assert np.abs(np.asarray(sim.positions) - positions).max() < 0.01 * np.abs(offset).max()


def test_apply_recalibrates_and_refuses():
    model = cylinder_model("any-nu-tet")
    with pytest.raises(hooke.InvalidArgument, match="local-global"):  # volume terms: local/global cannot run them
        hooke.LiveSimulation(model, integrator="local-global")
    sim = hooke.LiveSimulation(model)
    for _ in range(5):
        sim.step()
    sim.apply(poisson=0.45, method="any-nu-tet")
    fresh = hooke.calibrate(model.mesh, hooke.Material(14630.0, 0.45), "any-nu-tet")
    assert np.array_equal(sim.model.stiffness, fresh.stiffness)
    with pytest.raises(hooke.InvalidArgument, match="finite"):
        sim.apply(young=float("nan"))
    with pytest.raises(hooke.Error):
        sim.apply(method="surface")
    assert sim.model.material.nu == 0.45


def test_properties_are_copies_that_outlive_reset_and_apply():
    # positions, velocities and model were views into the simulator and an internal reference: apply() and reset()
    # replace what they pointed at, so arrays taken before read freed memory (7.0e9 was seen) afterwards.
    model = cylinder_model("any-nu-tet")
    sim = hooke.LiveSimulation(model, gravity=True)
    for _ in range(20):
        sim.step()
    x, v, m = sim.positions, sim.velocities, sim.model
    x0, v0, k0 = np.array(x), np.array(v), np.array(m.stiffness)
    sim.apply(poisson=0.45)
    sim.reset()
    junk = [np.full(x.shape, 7.0e9) for _ in range(50)]  # reuse what was freed
    assert np.array_equal(x, x0) and np.array_equal(v, v0)
    assert np.array_equal(m.stiffness, k0) and m.material.nu == 0.3
    assert np.abs(np.asarray(sim.positions) - np.asarray(model.mesh.points)).max() == 0.0  # reset: at rest
    assert len(junk) == 50


def test_a_device_thread_drags_while_another_steps():
    import threading

    model = cylinder_model("lloyd-tet")
    sim = hooke.LiveSimulation(model)
    node = top_node(model)
    sim.grab([node])
    stop = threading.Event()
    errors = []

    def device():
        k = 0
        try:
            while not stop.is_set():
                sim.drag([1e-6 * (k % 1000), 0.0, 0.0])
                assert np.isfinite(sim.positions).all()
                k += 1
        except Exception as e:  # reported below
            errors.append(e)

    t = threading.Thread(target=device)
    t.start()
    for _ in range(300):
        sim.step()
    stop.set()
    t.join()
    assert not errors
    assert abs(sim.time - 0.3) < 1e-12


def test_haptic_model_renders_between_steps():
    # A device's 1 kHz loop renders model.render(offset) between two deformation steps of 10 ms; after a slow drag
    # that has settled, the rendered force is the step's probe force, and it stiffens as the device pushes on.
    model = cylinder_model("any-nu-tet")
    sim = hooke.LiveSimulation(model, dt=0.01, damping_mass=60.0, haptic_stiffness="secant")
    node = top_node(model)
    sim.grab([node])
    for k in range(1, 101):
        sim.drag([1e-3 * min(1.0, k / 50), 0.0, 0.0])
        sim.step()
    h = sim.haptic_model()
    assert h.grabbed and h.version == 100
    assert np.allclose(h.render(h.offset), h.force)
    k = np.asarray(h.stiffness)
    assert k.shape == (3, 3) and k[0, 0] > 0.0 and np.allclose(k, k.T)
    pushed = np.asarray(h.render([1.1e-3, 0.0, 0.0]))
    assert pushed[0] < h.force[0]  # pushing further: the body pushes back harder (force along -x grows)
    # The second-order term: render = force - K d - T(d, d) / 2, and without it (haptic_curvature off) linear.
    t = np.asarray(h.curvature)
    assert t.shape == (3, 9) and np.abs(t).max() > 0.0
    d = np.array([1e-4, 0.0, 0.0])
    expected = np.asarray(h.force) - k @ d - 0.5 * np.array([d @ t[c].reshape(3, 3) @ d for c in range(3)])
    assert np.allclose(h.render(np.asarray(h.offset) + d), expected, rtol=0, atol=1e-12)
    sim.apply(haptic_curvature=False)
    sim.grab([node])
    sim.step()
    assert np.asarray(sim.haptic_model().curvature).size == 0
    with pytest.raises(hooke.InvalidArgument, match="haptic-curvature"):
        sim.apply(haptic_curvature="maybe")
    with pytest.raises(hooke.InvalidArgument, match="haptic stiffness"):
        sim.apply(haptic_stiffness="springy")


def test_the_local_model_made_in_the_background_is_the_one_made_in_place():
    # set_local_model_in_background(True), as the viewer's real-time loop: haptic_model() holds the force (stiffness
    # zero) until the job is done, then gives the condensed stiffness and curvature made in place.
    model = cylinder_model("any-nu-tet")
    node = top_node(model)
    in_place = hooke.LiveSimulation(model, dt=0.01, haptic_stiffness="condensed")
    background = hooke.LiveSimulation(model, dt=0.01, haptic_stiffness="condensed")
    background.set_local_model_in_background(True)
    for sim in (in_place, background):
        sim.grab([node])
        sim.step()
    expected = in_place.haptic_model()
    got = background.haptic_model()
    for _ in range(1000):
        if np.abs(np.asarray(got.stiffness)).max() > 0.0:
            break
        assert np.allclose(got.render(got.offset), got.force)  # meanwhile the force is held
        time.sleep(0.01)
        got = background.haptic_model()
    assert np.allclose(got.stiffness, expected.stiffness, rtol=1e-9, atol=0.0)
    assert np.asarray(got.curvature).shape == (3, 9)
    assert np.allclose(got.curvature, expected.curvature, rtol=1e-6, atol=1e-12 * np.abs(expected.curvature).max())


def test_a_tool_pressed_by_a_device_renders_its_force_from_the_local_contact_model():
    """A sphere driven 2 mm into the top (drive_tool, 10 ms steps): the haptic model carries the nodes near it; at
    the step's offset it renders the step's force, deeper it renders more, and the next step agrees within 5 %."""
    model = cylinder_model("any-nu-tet")
    sim = hooke.LiveSimulation(model, dt=0.01, damping_mass=60.0)
    top = np.asarray(model.mesh.points)[:, 2].max()
    sim.set_tool("sphere:0.005", [0.0, 0.0, top + 0.005 + 2e-4])
    for k in range(1, 61):
        sim.drive_tool([0.0, 0.0, -2.2e-3 * min(1.0, k / 30)])
        sim.step()
    h = sim.haptic_model()
    assert h.tool and h.contact_nodes > 0
    here = np.array(h.render(h.offset))
    assert np.allclose(here, sim.tool_force, rtol=1e-9, atol=1e-12)
    deeper = np.array(h.render(np.array(h.offset) + [0.0, 0.0, -1e-4]))
    assert deeper[2] > here[2] > 0.01
    sim.drive_tool(np.array(h.offset) + [0.0, 0.0, -1e-4])
    for _ in range(100):
        sim.step()
    assert abs(deeper[2] - sim.tool_force[2]) < 0.05 * sim.tool_force[2]
    with pytest.raises(ValueError, match="NaN"):
        sim.drive_tool([0.0, np.nan, 0.0])
    sim.remove_tool()
    assert sim.tool_force == []
