// Calibration and model files: hooke.calibrate / methods / read_model / write_model / certify, and hooke.Model,
// whose spring arrays are numpy views of the C++ model (no copies).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <bindings.hpp>
#include <core/arrays.hpp>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/calibrate/model_file.hpp>
#include <hooke/experiments/compare.hpp>

namespace py = pybind11;

namespace hooke::python {
namespace {

using calibrate::CalibratedModel;

py::dict certificate_case(const calibrate::CertificateCase& c) {
  py::dict d;
  d["load"] = c.load;
  d["strain"] = c.strain;
  d["max_error"] = c.max_error;
  d["mean_error"] = c.mean_error;
  d["relative_l2"] = c.relative_l2;
  return d;
}

}  // namespace

void define_model(py::module_& m) {
  py::class_<CalibratedModel>(m, "Model",
                              "A calibrated model: its mesh, springs (pairs, stiffness N/m, rest_length m), tet volume "
                              "terms, lumped masses (kg), the material, the method and its validity warnings.")
      .def_readonly("method", &CalibratedModel::method, "stable method name")
      .def_readonly("equation", &CalibratedModel::equation, "where the constants come from (paper, equation)")
      .def_readonly("meshing", &CalibratedModel::meshing,
                    "How the tets were made from a closed surface (mesher, options, counts, quality); empty otherwise")
      .def_readonly("choice", &CalibratedModel::choice,
                    "why method=\"auto\" chose this method (the measured errors compared); empty otherwise")
      .def_readonly("mesh", &CalibratedModel::mesh, py::return_value_policy::reference_internal, "the rest mesh (m)")
      .def_readonly("material", &CalibratedModel::material, "the material it was calibrated for")
      .def_readonly("density", &CalibratedModel::density, "kg/m^3, what the masses were made from")
      .def_readonly("warnings", &CalibratedModel::warnings, "the method's validity warnings (list of str)")
      .def_property_readonly(
          "pairs",
          [](py::object self) {
            auto& s = self.cast<CalibratedModel&>().springs;
            static_assert(sizeof(std::array<int, 2>) == 2 * sizeof(int));
            return view(s.pairs.empty() ? nullptr : s.pairs.front().data(), static_cast<Eigen::Index>(s.pairs.size()),
                        2, self, false);
          },
          "(S, 2) node indices of the springs (read-only view).")
      .def_property_readonly(
          "stiffness",
          flat_property<CalibratedModel>([](CalibratedModel& c) -> VecX& { return c.springs.stiffness; }, true),
          "(S,) spring stiffness k, N/m: a writable view (edited values are checked when the model is used).")
      .def_property_readonly(
          "rest_length",
          flat_property<CalibratedModel>([](CalibratedModel& c) -> VecX& { return c.springs.rest_length; }, true),
          "(S,) spring rest length l0, m (writable view).")
      .def_property_readonly(
          "volume_tets",
          [](py::object self) {
            auto& s = self.cast<CalibratedModel&>().springs;
            return view(s.volume_tets.data(), s.volume_tets.rows(), s.volume_tets.cols(), self, false);
          },
          "(T, 4) tets carrying a volume term, or (T, 3) triangles carrying an area term in 2D (empty without).")
      .def_property_readonly(
          "volume_stiffness",
          flat_property<CalibratedModel>([](CalibratedModel& c) -> VecX& { return c.springs.volume_stiffness; }, true),
          "(T,) volume term stiffness k_V, J.")
      .def_property_readonly(
          "rest_volume",
          flat_property<CalibratedModel>([](CalibratedModel& c) -> VecX& { return c.springs.rest_volume; }, false),
          "(T,) rest volume V0 per volume term, m^3.")
      .def_property_readonly(
          "masses", flat_property<CalibratedModel>([](CalibratedModel& c) -> VecX& { return c.masses; }, false),
          "(dim * N,) lumped mass per DOF, kg.")
      .def_property_readonly(
          "certificate",
          [](const CalibratedModel& c) {
            py::list l;
            for (const auto& k : c.certificate) l.append(certificate_case(k));
            return l;
          },
          "measured error against the linear FEM per load case (list of dict), empty until certified")
      .def_property_readonly(
          "is_surface_model", [](const CalibratedModel& c) { return c.surface.has_value(); },
          "True for the Arnab & Raja surface model")
      .def("__repr__", [](const CalibratedModel& c) {
        return "<hooke.Model " + c.method + ", " + std::to_string(c.mesh.node_count()) + " nodes, " +
               std::to_string(c.springs.pairs.size()) + " springs>";
      });

  m.def("methods", &calibrate::model_method_names,
        "The stable names calibrate() accepts: the calibration methods, then 'surface' and 'fem'.");
  m.def("method_equation", &calibrate::method_equation, py::arg("method"),
        "Where the constants of `method` come from (paper and equation).");
  m.def(
      "_calibrate",
      [](const mesh::Mesh& mesh, const material::Material& material, const std::string& method, double density,
         const mesh::TetrahedralizeOptions& tetrahedralize) {
        calibrate::ModelOptions o;
        o.method = method;
        o.density = density;
        o.tetrahedralize = tetrahedralize;
        py::gil_scoped_release release;
        return calibrate::calibrate_model(mesh, material, o);
      },
      py::arg("mesh"), py::arg("material"), py::arg("method"), py::arg("density"), py::arg("tetrahedralize"));
  m.def(
      "read_model",
      [](const std::filesystem::path& path) {
        py::gil_scoped_release release;
        return calibrate::read_model(path);
      },
      py::arg("path"),
      "Reads a model file (.json, schema of docs/model_format.md). Raises ParseError naming the file and the entry.");
  m.def(
      "write_model",
      [](const std::filesystem::path& path, const CalibratedModel& model) {
        calibrate::validate_model(model, path.string());
        calibrate::write_model(path, model);
      },
      py::arg("path"), py::arg("model"),
      "Writes the model as .json, .vtu (springs as lines) or .csv by extension, atomically.");
  m.def(
      "certify",
      [](CalibratedModel& model, double strain, int layers, const std::vector<std::string>& loads) {
        std::vector<model::LoadKind> kinds;
        for (const auto& name : loads) kinds.push_back(model::load_kind_from_name(name));
        std::vector<calibrate::CertificateCase> cases;
        {
          py::gil_scoped_release release;
          cases = experiments::certify(model, strain, layers, kinds);
        }
        model.certificate = cases;
        py::list l;
        for (const auto& k : cases) l.append(certificate_case(k));
        return l;
      },
      py::arg("model"), py::arg("strain") = 0.01, py::arg("layers") = 4,
      py::arg("loads") = std::vector<std::string>{"stretch", "compress", "shear"},
      "Stretch, compress and shear (or the `loads` named) at mean linear-FEM strain `strain` against the linear FEM: "
      "per case max / mean node error (m) and relative L2. Stored in model.certificate (written with the model).");
}

}  // namespace hooke::python
