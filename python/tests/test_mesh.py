"""Meshes from Python: zero-copy views, reading and writing, generators, and errors that carry the file facts."""
import numpy as np
import pytest

import hooke


def test_points_are_a_view_of_the_mesh(tmp_path):
    m = hooke.tet_box(0.01, 0.01, 0.02, 2, 2, 4)
    assert m.points.shape == (m.node_count, 3)
    assert m.elements.shape == (m.element_count, 4)
    p = m.points
    p[0, 0] += 1e-4  # writes through to the C++ mesh
    assert m.points[0, 0] == p[0, 0]
    assert np.shares_memory(m.points, m.points)
    with pytest.raises(ValueError):
        m.elements[0, 0] = 1  # read-only


def test_round_trip_through_a_file(tmp_path):
    m = hooke.tet_cylinder(0.01, 0.02, 12, 4)
    hooke.write_mesh(tmp_path / "c.msh", m)
    back = hooke.read_mesh(tmp_path / "c.msh")
    assert back.kind == "tet"
    np.testing.assert_allclose(back.points, m.points, rtol=0, atol=1e-15)
    np.testing.assert_array_equal(back.elements, m.elements)
    cm = hooke.read_mesh(tmp_path / "c.msh", unit="cm")
    np.testing.assert_allclose(cm.points, 0.01 * m.points)


def test_committed_mesh_reads(meshes):
    m = hooke.read_mesh(meshes / "cylinder_hole.msh")
    assert m.kind == "tet" and m.node_count == 990


def test_parse_error_names_file_and_line(tmp_path):
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n")
    with pytest.raises(hooke.ParseError) as e:
        hooke.read_mesh(bad)
    assert e.value.file.endswith("bad.off")
    assert e.value.line == 4
    assert isinstance(e.value, hooke.Error)


def test_invalid_mesh_names_the_element():
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]], dtype=float)
    tets = np.array([[0, 1, 2, 3], [0, 1, 2, 2]], dtype=np.int32)  # the second repeats a node
    with pytest.raises(hooke.InvalidMesh) as e:
        hooke.Mesh("tet", points, tets)
    assert e.value.element == 1


def test_wrong_shapes_and_nans_raise_value_error_naming_the_argument():
    tets = np.array([[0, 1, 2, 3]], dtype=np.int32)
    with pytest.raises(ValueError, match="points"):
        hooke.Mesh("tet", np.zeros((4, 2)), tets)
    with pytest.raises(ValueError, match="points"):
        hooke.Mesh("tet", np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, np.nan]]), tets)
    with pytest.raises(ValueError, match="elements"):
        hooke.Mesh("tet", np.eye(4, 3), np.array([[0.5, 1, 2, 3]]))


def test_meshio_round_trip():
    meshio = pytest.importorskip("meshio")
    m = hooke.tet_box(0.01, 0.01, 0.01, 2, 2, 2)
    mm = hooke.mesh_to_meshio(m)
    assert isinstance(mm, meshio.Mesh)
    back = hooke.mesh_from_meshio(mm)
    np.testing.assert_array_equal(back.elements, m.elements)


def test_tetrahedralize_a_closed_surface_and_calibrate_on_it():
    cube = hooke.cube_surface(4, 0.1)
    tets, report = hooke.tetrahedralize(cube)
    assert tets.kind == "tet"
    assert report["surface_preserved"]
    assert report["tets"] == len(tets.elements)
    assert abs(report["volume"] - 1e-3) < 1e-15
    assert report["min_radius_ratio"] > 0.0 and 0.0 < report["min_dihedral"] < 90.0
    # calibrate() tetrahedralizes a surface for a tet method, with the same options
    model = hooke.calibrate(cube, hooke.Material(1e5, 0.45), tetrahedralize={"size": 0.05})
    assert "netgen" in model.meshing and model.method == "stiffness-fit-volume"
    assert len(model.volume_tets) > 0
    surface_model = hooke.calibrate(cube, hooke.Material(1e5, 0.45), method="surface")
    assert surface_model.is_surface_model and surface_model.meshing == ""
    # TetGen's program as the mesher: the same report, the surface kept exactly
    tets, report = hooke.tetrahedralize(cube, mesher="tetgen")
    assert "tetgen" in report["mesher"] and report["surface_preserved"]
    assert abs(report["volume"] - 1e-3) < 1e-15
    model = hooke.calibrate(cube, hooke.Material(1e5, 0.45), tetrahedralize={"mesher": "tetgen", "size": 0.05})
    assert "tetgen" in model.meshing


def test_tetrahedralize_refusals_name_the_cause():
    cube = hooke.cube_surface(3, 1.0)
    with pytest.raises(hooke.InvalidArgument, match=r"unknown setting 'sise' \(known: mesher, size"):
        hooke.tetrahedralize(cube, sise=0.1)
    with pytest.raises(hooke.InvalidArgument, match="not both"):
        hooke.tetrahedralize(cube, size=0.1, max_volume=1e-3)
    with pytest.raises(hooke.InvalidMesh, match="quality floor"):
        hooke.tetrahedralize(cube, quality=0.99)
    with pytest.raises(hooke.InvalidArgument, match="mesher"):
        hooke.tetrahedralize(cube, mesher="gmsh")
    with pytest.raises(hooke.InvalidMesh, match="closed triangle surface"):
        hooke.tetrahedralize(hooke.tet_box(1, 1, 1, 1, 1, 1))
