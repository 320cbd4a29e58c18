"""hooke.identify from Python: the same study as `hooke identify`, from hooke's FEM and from arrays."""
import numpy as np
import pytest

import hooke


def cylinder():
    return hooke.tet_cylinder(0.01, 0.02, 4, 4)


def test_identify_from_fem_beats_the_analytic_model_on_held_out_cases():
    material = hooke.Material(14630.0, 0.45)
    model, report = hooke.identify(cylinder(), material, objective="positions", iterations=5, held_out=2)
    assert report["parameters"] == "springs+volume" and report["analytic_method"] == "any-nu-tet"
    assert len(report["cases"]) == 14 and sum(c["held_out"] for c in report["cases"]) == 2
    assert report["held_out_relative_l2_rms"] < report["analytic_held_out_relative_l2_rms"]
    assert model.method == "identified"
    assert model.stiffness.min() > 0.0 and model.volume_stiffness.shape == (model.volume_tets.shape[0],)


def test_identify_from_arrays_recovers_the_fem_cases_it_was_given():
    mesh = cylinder()
    material = hooke.Material(14630.0, 0.3)
    model, _ = hooke.identify(mesh, material, params="springs", held_out=0)
    # the identified model's own equilibrium as measured data: Eq. 2 finds that model again
    problem = hooke.Problem(model)
    x = mesh.points
    bottom = np.flatnonzero(x[:, 2] < x[:, 2].min() + 1e-9)
    top = np.flatnonzero(x[:, 2] > x[:, 2].max() - 1e-9)
    problem.fix_nodes(bottom.tolist())
    force = np.zeros_like(x)
    force[top, 0] = 1e-3
    problem.external_force = force.ravel()
    positions, _ = hooke.static_equilibrium(problem)
    fixed = np.zeros(len(x))
    fixed[bottom] = 1.0
    refit, report = hooke.identify(mesh, material, params="springs", stiffness_floor=0.0, references=[
        {"displacement": positions - x, "force": force, "fixed": fixed, "name": "shear"}])
    assert report["cases"][0]["name"] == "shear"
    assert report["force_residual"] < 1e-6


def test_identify_refuses_bad_references():
    mesh = cylinder()
    with pytest.raises(ValueError, match="displacement"):
        hooke.identify(mesh, hooke.Material(14630.0, 0.3), references=[{"force": np.zeros((mesh.node_count, 3))}])
    with pytest.raises(ValueError, match="force"):
        hooke.identify(mesh, hooke.Material(14630.0, 0.3),
                       references=[{"displacement": np.zeros((mesh.node_count, 3)), "force": np.zeros((3, 3))}])


def test_identify_passes_tolerance_and_negative_volume_through():
    mesh = cylinder()
    material = hooke.Material(14630.0, 0.1)
    # Eq. 2 alone: its solver's tolerance and the sign of the volume terms
    with pytest.raises(ValueError, match="tolerance"):
        hooke.identify(mesh, material, held_out=0, objective="forces", tolerance=0.0)
    loose, loose_report = hooke.identify(mesh, material, held_out=0, objective="forces", tolerance=1e-2)
    tight, tight_report = hooke.identify(mesh, material, held_out=0, objective="forces")
    assert loose_report["least_squares"]["cg_iterations"] < tight_report["least_squares"]["cg_iterations"]
    assert tight_report["tolerance"] == 1e-9 and not tight_report["negative_volume"]
    assert loose.volume_stiffness.min() >= 0.0
    # at nu = 0.1 the force fit wants negative volume terms (a spring network alone is a nu = 1/4 solid)
    free, free_report = hooke.identify(mesh, material, held_out=0, objective="forces", negative_volume=True)
    assert free.volume_stiffness.min() < 0.0
    assert free_report["force_residual"] < tight_report["force_residual"]


def test_identify_refuses_options_out_of_range():
    # the ranges are the library's (they were checked by the CLI alone: stiffness_floor=5 was taken)
    mesh = cylinder()
    material = hooke.Material(14630.0, 0.3)
    for kwargs, what in [({"stiffness_floor": 5.0}, "stiffness floor"), ({"regularize": -1.0}, "regularization"),
                         ({"iterations": -2}, "iterations")]:
        with pytest.raises(hooke.InvalidArgument, match=what):
            hooke.identify(mesh, material, **kwargs)


def test_identify_under_displacement_control_reports_and_fits_the_force():
    # FEM presses (the loaded nodes held and moved, the force on them measured): every case reports its force error,
    # and the measured forces fix the scale the positions alone cannot.
    mesh = cylinder()
    material = hooke.Material(14630.0, 0.45)
    model, report = hooke.identify(mesh, material, iterations=3, held_out=1, control="displacement")
    assert len(report["cases"]) == 13
    assert all(0.0 <= c["identified_force_error"] < 0.5 for c in report["cases"])
    traction_model, traction = hooke.identify(mesh, material, iterations=0, held_out=0)
    assert all(c["identified_force_error"] == -1.0 for c in traction["cases"])  # no instrument there
    # a reference dict marks held nodes with "prescribed"; a node cannot be both held by a support and prescribed
    x = mesh.points
    both = np.zeros(len(x))
    both[0] = 1.0
    data = {"displacement": np.zeros_like(x), "force": np.zeros_like(x), "fixed": both, "prescribed": both}
    with pytest.raises(hooke.InvalidArgument, match="both a support and prescribed"):
        hooke.identify(mesh, material, references=[data])
    with pytest.raises(hooke.InvalidArgument, match="FEM references"):
        hooke.identify(mesh, material, references=[data], control="displacement")
    with pytest.raises(hooke.InvalidArgument, match="control"):
        hooke.identify(mesh, material, control="sideways")
