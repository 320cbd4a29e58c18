// Meshes: hooke.Mesh with numpy views of its nodes and elements (no copies), reading and writing by extension, and
// the generators.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <bindings.hpp>
#include <core/arrays.hpp>
#include <core/settings.hpp>
#include <hooke/calibrate/model_settings.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/units.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/io/mesher.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/tetrahedralize.hpp>
#include <hooke/mesh/validate.hpp>

namespace py = pybind11;

namespace hooke::python {
namespace {

mesh::ElementKind kind_from_name(const std::string& name) {
  for (auto k : {mesh::ElementKind::kTriangle, mesh::ElementKind::kQuad, mesh::ElementKind::kTet,
                 mesh::ElementKind::kSurfaceTriangle})
    if (mesh::element_kind_name(k) == name) return k;
  throw py::value_error("kind: unknown element kind '" + name + "' (triangle, quad, tet, surface-triangle)");
}

}  // namespace

void define_mesh(py::module_& m) {
  py::class_<mesh::Mesh>(m, "Mesh", "A mesh of one element kind; coordinates in metres.")
      .def(py::init([](const std::string& kind, const py::object& points, const py::object& elements,
                       const std::string& source) {
             const mesh::ElementKind k = kind_from_name(kind);
             mesh::Mesh mesh =
                 mesh::make_mesh(k, matrix_argument(points, "points", -1, mesh::dimension(k)),
                                 index_argument(elements, "elements", mesh::nodes_per_element(k)), source);
             mesh::validate(mesh);
             return mesh;
           }),
           py::arg("kind"), py::arg("points"), py::arg("elements"), py::arg("source") = "",
           "Mesh(kind, points, elements): kind 'triangle', 'quad', 'tet' or 'surface-triangle'; points (N, dim) "
           "in m; elements (M, k) 0-based node indices. Validated (inverted elements reoriented, degenerate ones "
           "raise InvalidMesh).")
      .def_property_readonly(
          "points",
          [](py::object self) {
            auto& mesh = self.cast<mesh::Mesh&>();
            return view(mesh.nodes.data(), mesh.nodes.rows(), mesh.nodes.cols(), self, true);
          },
          "(N, dim) node positions in m: a writable view of the mesh's own array (no copy).")
      .def_property_readonly(
          "elements",
          [](py::object self) {
            auto& mesh = self.cast<mesh::Mesh&>();
            return view(mesh.elements.data(), mesh.elements.rows(), mesh.elements.cols(), self, false);
          },
          "(M, k) 0-based node indices: a read-only view (editing it could break the mesh's validity).")
      .def_property_readonly(
          "kind", [](const mesh::Mesh& mesh) { return std::string(element_kind_name(mesh.kind)); },
          "\'triangle\', \'quad\', \'tet\' or \'surface-triangle\'")
      .def_property_readonly(
          "region",
          [](py::object self) {
            auto& mesh = self.cast<mesh::Mesh&>();
            return flat_view(mesh.region.data(), mesh.region.size(), self, true);
          },
          "(M,) region tag per element (Gmsh physical group, VTU `region`, TetGen attribute; 0 where the file has "
          "none): a writable view, so that elements can be put in regions before calibrate(materials=...)")
      .def_property_readonly("dim", &mesh::Mesh::dim, "coordinate dimension, 2 or 3")
      .def_property_readonly("node_count", &mesh::Mesh::node_count, "number of nodes N")
      .def_property_readonly("element_count", &mesh::Mesh::element_count, "number of elements M")
      .def_readonly("source", &mesh::Mesh::source, "the file or generator it came from (used in messages)")
      .def("__repr__", [](const mesh::Mesh& mesh) {
        return "<hooke.Mesh " + std::string(element_kind_name(mesh.kind)) + ", " + std::to_string(mesh.node_count()) +
               " nodes, " + std::to_string(mesh.element_count()) + " elements>";
      });

  m.def(
      "read_mesh",
      [](const std::filesystem::path& path, const std::string& unit, bool validate) {
        io::ReadOptions o;
        o.metres_per_unit = metres_per_unit(unit);
        o.validate = validate;
        py::gil_scoped_release release;
        return io::read_mesh(path, o);
      },
      py::arg("path"), py::arg("unit") = "m", py::arg("validate") = true,
      "Reads .msh, .vtu, .node/.ele/.face, .obj, .off or .stl; coordinates scaled from `unit` (m, cm, mm) to m. "
      "Raises ParseError (with .file, .line), IoError or InvalidMesh (with .element).");
  m.def(
      "write_mesh",
      [](const std::filesystem::path& path, const mesh::Mesh& mesh, bool binary) {
        io::WriteOptions o;
        o.binary = binary;
        io::write_mesh(path, mesh, o);
      },
      py::arg("path"), py::arg("mesh"), py::arg("binary") = false,
      "Writes the mesh in the format of the extension, atomically (a temporary file renamed when complete).");
  m.def("tet_box", &mesh::tet_box, py::arg("lx"), py::arg("ly"), py::arg("lz"), py::arg("nx"), py::arg("ny"),
        py::arg("nz"), "A box [0, lx] x [0, ly] x [0, lz] (m) of nx x ny x nz cells, six tets per cell.");
  m.def("tet_cylinder", &mesh::tet_cylinder, py::arg("radius"), py::arg("height"), py::arg("n"), py::arg("layers"),
        "A tet cylinder of radius and height (m) on the z axis: an O-grid cross-section with n cells around, "
        "`layers` layers.");
  m.def(
      "rectangle_triangles", [](double w, double h, int nx, int ny) { return mesh::rectangle_triangles(w, h, nx, ny); },
      py::arg("width"), py::arg("height"), py::arg("nx"), py::arg("ny"),
      "A w x h rectangle (m) of nx x ny cells, two triangles each.");
  m.def("equilateral_membrane", &mesh::equilateral_membrane, py::arg("rows"), py::arg("long_row"), py::arg("edge"),
        "A planar membrane of equilateral triangles (edge in m): rows of long_row and long_row - 1 nodes; (7, 6, "
        "0.01) is Lloyd et al.'s Sec. 5.1 membrane of 39 nodes.");
  m.def("hexagon_membrane", &mesh::hexagon_membrane, py::arg("rings"), py::arg("side"),
        "A regular hexagon of side `side` (m) of equilateral triangles, `rings` triangles from the centre to each side "
        "(Lloyd et al.'s Fig. 3).");
  m.def("rectangle_quads", &mesh::rectangle_quads, py::arg("width"), py::arg("height"), py::arg("nx"), py::arg("ny"),
        "A width x height rectangle (m) of nx x ny bilinear quads.");
  m.def(
      "tetrahedralise_radially",
      [](const mesh::Mesh& surface, const py::object& centre, int layers) {
        return mesh::tetrahedralise_radially(surface, vector_argument(centre, "centre", 3), layers);
      },
      py::arg("surface"), py::arg("centre"), py::arg("layers"),
      "Tets filling a closed surface star-shaped about `centre` (m), in `layers` layers towards it.");
  m.def("_tetrahedralize_options", [](const py::kwargs& kwargs) {
    // The declared tet settings (calibrate::model_settings, settings::kMesh), the library's defaults for the rest.
    calibrate::ModelOptions o;
    settings::apply(calibrate::model_settings(), o, given_settings(kwargs), settings::kMesh);
    return o.tetrahedralize;
  });
  py::class_<mesh::TetrahedralizeOptions>(m, "_TetrahedralizeOptions");
  m.def(
      "_tetrahedralize",
      [](const mesh::Mesh& surface, const mesh::TetrahedralizeOptions& o) {
        mesh::TetrahedralizeReport r;
        mesh::Mesh tets;
        {
          py::gil_scoped_release release;
          tets = io::tetrahedralize(surface, o, &r);
        }
        py::dict d;
        d["mesher"] = r.backend;
        d["surface_mesh"] = std::string(mesh::surface_meshing_name(r.options.surface));
        d["size"] = r.options.max_size;
        d["surface_nodes"] = r.surface_nodes;
        d["surface_triangles"] = r.surface_triangles;
        d["surface_volume"] = r.surface_volume;
        d["nodes"] = r.nodes;
        d["tets"] = r.tets;
        d["volume"] = r.volume;
        d["volume_error"] = r.volume_error;
        d["surface_preserved"] = r.surface_preserved;
        d["hausdorff"] = r.hausdorff;
        d["min_radius_ratio"] = r.quality.min_radius_ratio;
        d["mean_radius_ratio"] = r.quality.mean_radius_ratio;
        d["min_dihedral"] = r.quality.min_dihedral;
        d["max_dihedral"] = r.quality.max_dihedral;
        d["worst_element"] = r.quality.worst_element;
        d["slivers"] = r.slivers;
        d["seconds"] = r.seconds;
        d["summary"] = r.summary();
        return py::make_tuple(tets, d);
      },
      py::arg("surface"), py::arg("options"));
  m.def("cube_surface", &mesh::cube_surface, py::arg("n"), py::arg("size"),
        "The closed triangulated surface of a cube of edge `size` (m), n x n squares per face.");
  m.def("uv_sphere_surface", &mesh::uv_sphere_surface, py::arg("rings"), py::arg("segments"), py::arg("radius"),
        "A closed UV sphere surface of `radius` (m).");
}

}  // namespace hooke::python
