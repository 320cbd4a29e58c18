"""Checks of the module against independent computations: a CST stiffness assembled in numpy, the CLI's numbers,
zero-copy state views, and every exception type with its attributes."""
import os
import re
import subprocess
import tracemalloc

import numpy as np
import pytest

import hooke


def cst_stiffness(points, triangles, young, nu, thickness):
    """Plane-stress CST stiffness, K_e = t A B^T D B, assembled densely (independent of hooke)."""
    n = len(points)
    k = np.zeros((2 * n, 2 * n))
    d = young / (1 - nu * nu) * np.array([[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]])
    for tri in triangles:
        (x1, y1), (x2, y2), (x3, y3) = points[tri]
        area2 = (x2 - x1) * (y3 - y1) - (x3 - x1) * (y2 - y1)
        b = np.array([y2 - y3, y3 - y1, y1 - y2]) / area2
        c = np.array([x3 - x2, x1 - x3, x2 - x1]) / area2
        bm = np.zeros((3, 6))
        bm[0, 0::2] = b
        bm[1, 1::2] = c
        bm[2, 0::2] = c
        bm[2, 1::2] = b
        ke = thickness * abs(area2) / 2 * bm.T @ d @ bm
        dofs = np.ravel([[2 * i, 2 * i + 1] for i in tri])
        k[np.ix_(dofs, dofs)] += ke
    return k


def test_lloyd_equilateral_springs_are_the_cst_stiffness_at_nu_one_third():
    pytest.importorskip("scipy")
    mesh = hooke.equilateral_membrane(7, 6, 0.01)
    assert mesh.node_count == 39
    young, nu, t = 14630.0, 1.0 / 3.0, 0.001
    model = hooke.calibrate(mesh, hooke.Material(young, nu, thickness=t), "lloyd-equilateral")
    springs = hooke.stiffness(hooke.Problem(model)).toarray()
    cst = cst_stiffness(mesh.points, mesh.elements, young, nu, t)
    assert np.abs(springs - cst).max() <= 1e-12 * np.abs(cst).max()


def test_compare_gives_the_numbers_of_the_cli(tmp_path, meshes):
    cli = os.environ.get("HOOKE_CLI")
    if not cli:
        pytest.skip("HOOKE_CLI (the hooke executable) not given")
    out = subprocess.run([cli, "compare", str(meshes / "cylinder_hole.msh"), "--young", "14630", "--poisson", "0.3",
                          "--method", "lloyd-tet", "--load", "shear", "--strain", "0.01", "--no-figure", "-o",
                          str(tmp_path / "cmp")], check=True, capture_output=True, text=True).stdout
    m = re.search(r"error\s+max ([0-9.e+-]+) m .* mean ([0-9.e+-]+) m .* relative L2 ([0-9.e+-]+)", out)
    assert m, out
    model = hooke.calibrate(hooke.read_mesh(meshes / "cylinder_hole.msh"), hooke.Material(14630.0, 0.3), "lloyd-tet")
    c = hooke.compare(model, "shear", strain=0.01)
    for ours, printed in ((c.max_error, m.group(1)), (c.mean_error, m.group(2)), (c.relative_l2, m.group(3))):
        assert ours == pytest.approx(float(printed), rel=1e-3)  # the CLI prints 4 significant digits


def test_state_views_are_zero_copy_and_read_only():
    mesh = hooke.tet_cylinder(0.01, 0.02, 12, 4)
    model = hooke.calibrate(mesh, hooke.Material(14630.0, 0.25), "lloyd-tet")
    p = hooke.Problem(model)
    p.apply_load("stretch", traction=0.0)
    sim = hooke.Simulator(p, "local-global", gravity=[0.0, 0.0, -9.81])
    x = sim.positions
    address = x.__array_interface__["data"][0]
    with pytest.raises(ValueError, match="read-only"):
        x[0, 0] = 1.0
    sim.step(1e-3)
    tracemalloc.start()
    before = tracemalloc.take_snapshot()
    for _ in range(20):
        sim.step(1e-3)
    after = tracemalloc.take_snapshot()
    tracemalloc.stop()
    grown = sum(s.size_diff for s in after.compare_to(before, "filename") if s.size_diff > 0)
    assert grown < 4096  # no array per step (a 3 x 87 copy alone would be 2 kB each step)
    assert sim.positions.__array_interface__["data"][0] == address  # the same buffer, stepped in place
    assert x[:, 2].min() < mesh.points[:, 2].min() + 1e-12  # the old view sees the new state
    assert not np.array_equal(x, mesh.points)


def test_every_exception_type_with_its_attributes(tmp_path):
    with pytest.raises(hooke.IoError):
        hooke.read_mesh(tmp_path / "missing.msh")
    bad = tmp_path / "bad.msh"
    bad.write_text("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\nbroken\n")
    with pytest.raises(hooke.ParseError) as e:
        hooke.read_mesh(bad)
    assert e.value.file.endswith("bad.msh") and e.value.line >= 5
    with pytest.raises(hooke.InvalidMesh) as e:
        hooke.Mesh("triangle", np.array([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]), np.array([[0, 1, 2]], dtype=np.int32))
    assert e.value.element == 0
    with pytest.raises(hooke.InvalidMaterial):
        hooke.Material(-1.0, 0.3)
    with pytest.raises(hooke.InvalidArgument):
        hooke.Problem(hooke.calibrate(hooke.tet_box(0.01, 0.01, 0.01, 1, 1, 1), hooke.Material(1e3, 0.25))).fix_nodes([99])
    with pytest.raises(hooke.SolverFailure) as e:
        p = hooke.Problem(hooke.calibrate(hooke.tet_box(0.01, 0.01, 0.01, 1, 1, 1), hooke.Material(1e3, 0.25)))
        p.external_force = np.ones(3 * 8)
        hooke.static_equilibrium(p)
    assert e.value.report.status == "singular"
    for t in (hooke.IoError, hooke.ParseError, hooke.InvalidMesh, hooke.InvalidMaterial, hooke.InvalidArgument,
              hooke.SolverFailure):
        assert issubclass(t, hooke.Error)


def test_fem_solve_and_meshio_methods():
    mesh = hooke.tet_box(0.01, 0.01, 0.02, 2, 2, 4)
    x, report = hooke.fem.solve(mesh, hooke.Material(14630.0, 0.3), "stretch", strain=0.01)
    assert report.converged
    top = mesh.points[:, 2] == mesh.points[:, 2].max()
    assert (x[top, 2] - mesh.points[top, 2]).mean() == pytest.approx(0.01 * 0.02, rel=1e-9)  # mean top strain 1 %
    pytest.importorskip("meshio")
    back = hooke.Mesh.from_meshio(mesh.to_meshio())
    np.testing.assert_array_equal(back.elements, mesh.elements)
