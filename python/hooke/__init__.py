"""hooke: mass-spring models calibrated from Young's modulus and Poisson's ratio, checked against FEM.

The compiled core is ``hooke._hooke``; this layer adds Python warnings for the methods' validity warnings, the
scipy / meshio conversions, and checks of arguments the core cannot see.

Units are SI throughout: metres, pascals, newtons, kilograms, seconds.
"""
import logging as _logging
import warnings as _warnings

from ._hooke import (  # noqa: F401
    Comparison,
    Error,
    InvalidArgument,
    InvalidMaterial,
    InvalidMesh,
    IoError,
    HapticModel,
    LiveSimulation,
    Material,
    Mesh,
    Model,
    ParseError,
    Problem,
    Simulator,
    SolveReport,
    StepReport,
    Tool,
    SolverFailure,
    __version__,
    certify,
    compare,
    compare_under_contact,
    cube_surface,
    equilateral_membrane,
    fem_probe_equilibrium,
    hexagon_membrane,
    linear_static,
    method_equation,
    press,
    methods,
    read_mesh,
    read_model,
    rectangle_quads,
    rectangle_triangles,
    static_equilibrium,
    tet_box,
    tet_cylinder,
    tetrahedralise_radially,
    uv_sphere_surface,
    write_mesh,
    write_model,
)
from . import _hooke
from . import fem  # noqa: F401  (hooke.fem.solve)

SpringModel = Model

# The library's log messages reach the "hooke" logger; silent unless the application configures logging.
_logging.getLogger("hooke").addHandler(_logging.NullHandler())


class ValidityWarning(UserWarning):
    """A calibration method used outside the conditions its derivation assumes (e.g. Lloyd et al.'s springs away
    from nu = 1/4)."""


def _keyword_help(command):
    """The keywords of `command`'s declared settings (hooke._settings), one per line, for a docstring."""
    lines = []
    for d in _hooke._settings(command):
        default = " (default %s)" % d["default"] if d["default"] else ""
        lines.append("    %-19s %s%s" % (d["keyword"], d["long_help"], default))
    return "\n".join(lines)


def settings(command):
    """The declared settings of `command` ("calibrate", "compare", "simulate", "view", "batch", "mesh", "bench"), as
    a list of dicts: name (the CLI's --NAME), keyword (the Python keyword and batch column), type, unit, help, default,
    min, max, choices and commands. Every front end's options are made from these declarations."""
    return _hooke._settings(command)


def tetrahedralize(surface, **options):
    if not isinstance(surface, Mesh):
        raise TypeError("tetrahedralize: surface must be a hooke.Mesh")
    return _hooke._tetrahedralize(surface, _hooke._tetrahedralize_options(**options))


tetrahedralize.__doc__ = """Fills the closed triangle surface `surface` (hooke.Mesh, m) with tets (Netgen or TetGen), after
checking it is closed, manifold and not crossing itself (errors name the element). docs/meshing.md.

Keywords (the library's defaults otherwise; lengths in m):
""" + _keyword_help("mesh") + """

Returns (mesh, report): the tet hooke.Mesh and a dict (nodes, tets, volume_error, hausdorff, min_radius_ratio,
min_dihedral, slivers, seconds, summary, ...).
"""


def calibrate(mesh, material, method=None, tetrahedralize=None, materials=None, **options):
    if not isinstance(mesh, Mesh):
        raise TypeError("calibrate: mesh must be a hooke.Mesh")
    if not isinstance(material, Material):
        raise TypeError("calibrate: material must be a hooke.Material")
    if method is not None:
        options["method"] = method
    for key, value in (tetrahedralize or {}).items():  # the tet keywords, also accepted grouped in a dict
        options.setdefault(key, value)
    regions = []
    for region, value in (materials or {}).items():  # {region: (E, nu)} or {region: hooke.Material}
        if isinstance(value, Material):
            value = (value.E, value.nu)
        young, poisson = value
        regions.append((int(region), float(young), float(poisson)))
    model = _hooke._calibrate(mesh, material, options, regions)
    for w in model.warnings:
        _warnings.warn(w, ValidityWarning, stacklevel=2)
    return model


calibrate.__doc__ = """Calibrates a model on `mesh` (hooke.Mesh, m; a closed surface-triangle mesh is tetrahedralized
first for every method but "surface", and .meshing says how) for `material` (hooke.Material: E in Pa, nu; thickness in
m for 2D meshes), as `hooke calibrate` does. method="auto" (the default) picks the method of smallest measured error
for the mesh's element kind and nu; the model's .method is the one picked and .choice says why. With strain_range > 0
the springs' and volume terms' large-strain law is fitted to the FEM of `law` up to that strain
(docs/methods/large_strain.md); with certify=True the model's .certificate holds its measured error against FEM.
materials={region: (E, nu)} (or {region: hooke.Material}) gives the elements of those regions (mesh.region) their own
E and nu, as `--material REGION=E,NU` does; `material` is then the other elements' (docs/regions.md).

Keywords (each one of hooke.settings("calibrate"), unknown ones refused; `tetrahedralize` may group the tet keywords
in a dict):
""" + _keyword_help("calibrate") + """

Returns a hooke.Model: .pairs (S, 2), .stiffness (S,) N/m, .rest_length (S,) m, .volume_tets (T, 4),
.volume_stiffness (T,) J, .rest_volume (T,) m^3, .masses (dim * N,) kg. The method's validity warnings are issued as
hooke.ValidityWarning (and kept in .warnings).
"""


def stiffness(problem):
    """The model's Hessian at rest (its linearised stiffness), N/m, as a scipy.sparse.csr_matrix (dim*N square).

    Needs scipy."""
    import scipy.sparse

    data, indices, indptr, shape = problem.stiffness_csr()
    return scipy.sparse.csr_matrix((data, indices, indptr), shape=shape)


def reproduce(paper, out_dir, meshes=None, **options):
    """Runs a paper's experiments as `hooke reproduce` does ("lloyd2007": Sec. 5, Figs. 1 and 3; "arnab2008": Tables
    1-2, Figs. 8-12; "nu-range": every calibration method against the FEM over nu, small and large strain), writes
    the report (<paper>.md, .json; nu-range: nu_range.md, nu_range.json, method_table.inc) and the figure specs
    (figures/*.json; `hooke reproduce` renders them), and returns the JSON report as a dict (every number of the
    report). `meshes`: the folder of the committed meshes (default: the source tree's data/meshes). nu-range takes
    the study's options as keywords (`hooke reproduce nu-range --help`, dashes as underscores): poisson, methods,
    triangle_methods, planes, study_meshes, loads, small_strain, large_strain, laws (a list of {"law": L,
    "strain": S}: the displacement-controlled law regimes, Hookean and fitted terms; [] for none), fit_refinements."""
    import json
    import pathlib

    out = pathlib.Path(out_dir)
    mesh_dir = pathlib.Path(meshes) if meshes else pathlib.Path(_hooke._default_mesh_dir)
    if paper != "nu-range":
        if options:
            raise TypeError("reproduce: %s takes no options (%s)" % (paper, ", ".join(sorted(options))))
        _hooke._reproduce(paper, out, mesh_dir)
        return json.loads((out / (paper + ".json")).read_text())
    study = json.loads(_hooke._nu_range_default_options())
    if "study_meshes" in options:
        options["meshes"] = options.pop("study_meshes")
    unknown = sorted(set(options) - set(study))
    if unknown:
        raise TypeError("reproduce: unknown nu-range option(s) %s (known: %s)" % (", ".join(unknown), ", ".join(sorted(study))))
    study.update(options)
    _hooke._reproduce(paper, out, mesh_dir, json.dumps(study))
    return json.loads((out / "nu_range.json").read_text())


def identify(mesh, material, params="auto", objective="positions", references=None, strain=0.01, held_out=4, seed=2007,
             regularize=0.0, stiffness_floor=1e-3, iterations=30, compare="auto", density=1000.0, tolerance=1e-9,
             negative_volume=False, control="traction"):
    """Identifies a spring model from reference deformations (Lloyd et al. 2007: Eq. 2 `objective="forces"`, Eq. 1
    `objective="positions"`), as `hooke identify` does (docs/methods/identification.md).

    mesh        hooke.Mesh (tets, or planar triangles with params="springs"), m
    material    hooke.Material: E (Pa), nu, and the law of the FEM reference
    params      "springs", "springs+volume", "springs+volume+rest-length" or "auto" (springs+volume on tets)
    references  None: 12 load cases in every direction from hooke's FEM at `strain`, plus `held_out` random ones
                kept out of the fit; or a list of dicts {"displacement": (N, dim) m, "force": (N, dim) N applied,
                "fixed": (N,) 1.0 at supports, "held_out": bool, "name": str} (measured data)
    regularize  weight of the penalty toward the mean stiffness; stiffness_floor: smallest k / mean k
    iterations  Eq. 1 iterations at most; compare: the analytic model measured beside it ("auto": any-nu-tet)
    tolerance   Eq. 2 stops when its projected gradient is this fraction of U^T f, in (0, 1); 1e-2 suffices
                for large meshes (the force residual is then within 0.3 % of its minimum)
    negative_volume  let volume terms be negative: needed for nu < 1/4 (a spring network alone has nu = 1/4)
    control     FEM references: "traction" (a load on the loaded facets) or "displacement" (their nodes moved by strain
                x the extent; the force holding them is measured and fitted, and each case reports its force error).
                A reference dict marks such nodes with "prescribed": (N,) 1.0 where held, its "force" the reaction

    Returns (model, report): a hooke.Model (method "identified", ready for hooke.Problem and write_model) and the
    report as a dict (per case the identified and analytic relative L2 errors, RMS training and held-out errors,
    the solver's iterations, the k range, times)."""
    import json

    if not isinstance(mesh, Mesh):
        raise TypeError("identify: mesh must be a hooke.Mesh")
    if not isinstance(material, Material):
        raise TypeError("identify: material must be a hooke.Material")
    model, report = _hooke._identify(mesh, material, params, objective, references, float(strain), int(held_out),
                                     int(seed), float(regularize), float(stiffness_floor), int(iterations), compare,
                                     float(density), float(tolerance),
                                     bool(negative_volume), str(control))
    return model, json.loads(report)


def mesh_from_meshio(m):
    """A hooke.Mesh from a meshio.Mesh (its first cell block of tetra, triangle or quad)."""
    kinds = {"tetra": "tet", "quad": "quad"}
    for block in m.cells:
        if block.type in kinds or block.type == "triangle":
            if block.type == "triangle":
                planar = m.points.shape[1] == 2 or abs(m.points[:, 2]).max() == 0.0
                kind = "triangle" if planar else "surface-triangle"
                points = m.points[:, :2] if planar else m.points
            else:
                kind = kinds[block.type]
                points = m.points if kind == "tet" else m.points[:, :2]
            return Mesh(kind, points, block.data.astype("int32"), "meshio")
    raise ValueError("mesh_from_meshio: no tetra, triangle or quad cells")


def mesh_to_meshio(mesh):
    """The hooke.Mesh as a meshio.Mesh (needs meshio)."""
    import meshio
    import numpy

    cell = {"tet": "tetra", "triangle": "triangle", "surface-triangle": "triangle", "quad": "quad"}[mesh.kind]
    return meshio.Mesh(numpy.array(mesh.points), [(cell, numpy.array(mesh.elements))])


Mesh.from_meshio = staticmethod(mesh_from_meshio)
Mesh.to_meshio = mesh_to_meshio
