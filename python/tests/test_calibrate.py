"""Calibration and model files from Python, checked against the C++ CLI's numbers and against the model's own
assembled stiffness."""
import json
import warnings

import numpy as np
import pytest

import hooke


def test_methods_are_the_stable_names():
    names = hooke.methods()
    assert "lloyd-tet" in names and "surface" in names and "fem" in names


def test_lloyd_tet_on_the_cylinder_matches_the_model_file(tmp_path, meshes):
    mesh = hooke.read_mesh(meshes / "cylinder_hole.msh")
    model = hooke.calibrate(mesh, hooke.Material(14630.0, 0.25), "lloyd-tet")
    assert model.pairs.shape == (5516, 2)
    assert model.stiffness.shape == (5516,) and (model.stiffness > 0).all()
    assert model.masses.shape == (3 * 990,)
    hooke.write_model(tmp_path / "m.json", model)
    data = json.loads((tmp_path / "m.json").read_text())
    # The file holds the same springs: i, j, k, l0.
    springs = np.array(data["springs"], dtype=float)
    np.testing.assert_array_equal(springs[:, :2].astype(int), model.pairs)
    np.testing.assert_array_equal(springs[:, 2], model.stiffness)
    back = hooke.read_model(tmp_path / "m.json")
    np.testing.assert_array_equal(back.stiffness, model.stiffness)
    np.testing.assert_array_equal(back.rest_length, model.rest_length)


def test_validity_warnings_become_python_warnings():
    mesh = hooke.tet_box(0.01, 0.01, 0.02, 2, 2, 4)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        model = hooke.calibrate(mesh, hooke.Material(1000.0, 0.45), "lloyd-tet")
    assert model.warnings
    assert any(issubclass(w.category, hooke.ValidityWarning) for w in caught)


def test_invalid_material_and_method():
    with pytest.raises(hooke.InvalidMaterial):
        hooke.Material(1000.0, 0.5)
    with pytest.raises(hooke.InvalidArgument):
        hooke.calibrate(hooke.tet_box(0.01, 0.01, 0.01, 1, 1, 1), hooke.Material(1e3, 0.3), "no-such-method")
    with pytest.raises(ValueError):  # InvalidArgument is a ValueError too
        hooke.calibrate(hooke.tet_box(0.01, 0.01, 0.01, 1, 1, 1), hooke.Material(1e3, 0.3), "no-such-method")


def test_malformed_model_file_names_the_entry(tmp_path):
    mesh = hooke.tet_box(0.01, 0.01, 0.01, 1, 1, 1)
    hooke.write_model(tmp_path / "m.json", hooke.calibrate(mesh, hooke.Material(1e3, 0.25)))
    data = json.loads((tmp_path / "m.json").read_text())
    data["springs"][2][2] = -5.0
    (tmp_path / "bad.json").write_text(json.dumps(data))
    with pytest.raises(hooke.Error, match=r"springs\[2\]"):
        hooke.read_model(tmp_path / "bad.json")


def test_spring_stiffness_is_the_assembled_hessian():
    """Independent check: the linearised stiffness from scipy equals sum_s k_s n n^T over the springs."""
    pytest.importorskip("scipy")
    mesh = hooke.tet_box(0.01, 0.01, 0.01, 2, 2, 2)
    model = hooke.calibrate(mesh, hooke.Material(1e4, 0.25), "lloyd-tet")
    k = hooke.stiffness(hooke.Problem(model)).toarray()
    expected = np.zeros_like(k)
    x = mesh.points
    for (i, j), ks in zip(model.pairs, model.stiffness):
        n = x[j] - x[i]
        block = ks * np.outer(n, n) / n.dot(n)
        for a, b, s in ((i, i, 1), (j, j, 1), (i, j, -1), (j, i, -1)):
            expected[3 * a:3 * a + 3, 3 * b:3 * b + 3] += s * block
    np.testing.assert_allclose(k, expected, atol=1e-9 * abs(expected).max())


def test_certify_matches_compare():
    mesh = hooke.tet_cylinder(0.01, 0.02, 12, 4)
    model = hooke.calibrate(mesh, hooke.Material(14630.0, 0.3), "lloyd-tet")
    cert = hooke.certify(model, strain=0.01)
    assert [c["load"] for c in cert] == ["stretch", "compress", "shear"]
    c = hooke.compare(model, "stretch", strain=0.01)
    # Both converge the model's statics to Newton's tolerance (1e-9 of the force scale); certify starts with one
    # load step, compare with four, so they agree to that tolerance, not to the last bit.
    assert c.relative_l2 == pytest.approx(cert[0]["relative_l2"], rel=1e-8)
    assert c.node_error.shape == (mesh.node_count,)
    assert c.fem_positions.shape == (mesh.node_count, 3)
    np.testing.assert_allclose(np.linalg.norm(c.model_positions - c.fem_positions, axis=1), c.node_error)


def test_reproduce_arnab2008_returns_the_report_as_a_dict(tmp_path):
    report = hooke.reproduce("arnab2008", tmp_path)
    assert (tmp_path / "arnab2008.md").exists()
    table1 = report["table1"]
    assert len(table1) >= 3
    assert all(abs(row["deviation_percent"]) < 5.0 for row in table1)  # the paper's Table 1 within a few percent
    with pytest.raises(hooke.InvalidArgument):
        hooke.reproduce("smith1999", tmp_path)


def test_reproduce_nu_range_takes_the_studys_options(tmp_path, meshes):
    report = hooke.reproduce("nu-range", tmp_path, meshes, poisson=[0.3], methods=["lloyd-tet", "any-nu-tet"],
                             study_meshes=["cylinder_hole"], loads=["stretch"], large_strain=0.0, laws=[])
    assert (tmp_path / "nu_range.md").exists() and (tmp_path / "method_table.inc").exists()
    rows = report["rows"]
    assert {r["method"] for r in rows} == {"lloyd-tet", "any-nu-tet"}
    assert all(r["poisson"] == 0.3 and r["load"] == "stretch" and 0.0 < r["relative_l2"] < 0.5 for r in rows)
    with pytest.raises(TypeError, match="unknown nu-range option"):
        hooke.reproduce("nu-range", tmp_path, nus=[0.3])


def test_auto_picks_by_kind_and_plane_and_says_why():
    import pathlib

    mesh = hooke.read_mesh(str(pathlib.Path(__file__).parents[2] / "data" / "meshes" / "rectangle_tri.msh"))
    for plane in ("stress", "strain"):
        material = hooke.Material(14630.0, 0.45, thickness=0.001, plane=plane)
        assert material.plane == plane
        model = hooke.calibrate(mesh, material)
        assert model.method == "any-nu-triangle"
        assert ("plane-" + plane) in model.choice
    with pytest.raises(hooke.InvalidArgument, match="plane"):
        hooke.Material(14630.0, 0.3, plane="shear")
