// hooke.Model: a calibrated model, whose spring arrays are numpy views of the C++ model (no copies).
#include <pybind11/stl.h>
#include <bindings.hpp>
#include <calibrate/calibrated_model.hpp>
#include <core/arrays.hpp>

namespace py = pybind11;

namespace hooke::python {

using calibrate::CalibratedModel;

py::dict certificate_case(const calibrate::CertificateCase& c) {
  py::dict d;
  d["load"] = c.load;
  d["strain"] = c.strain;
  d["max_error"] = c.max_error;
  d["mean_error"] = c.mean_error;
  d["relative_l2"] = c.relative_l2;
  d["control"] = c.control;
  d["reference"] = c.reference;
  d["force_error"] = c.force_error;
  return d;
}

void define_calibrated_model(py::module_& m) {
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
      .def_property_readonly(
          "regions",
          [](const CalibratedModel& model) {
            py::dict out;
            for (const calibrate::RegionMaterial& r : model.regions)
              out[py::int_(r.region)] = py::make_tuple(r.youngs_modulus, r.poisson_ratio);
            return out;
          },
          "{region: (E in Pa, nu)} of the element regions with their own material (mesh.region); the other "
          "elements have .material's. Empty for one material.")
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
          "spring_exponent", [](const CalibratedModel& c) { return c.springs.spring_exponent; },
          "Seth-Hill exponent m of the springs' large-strain law (1: Hookean)")
      .def_property_readonly(
          "volume_exponent", [](const CalibratedModel& c) { return c.springs.volume_exponent; },
          "Seth-Hill exponent q of the volume terms' large-strain law (1: quadratic)")
      .def_property_readonly(
          "is_surface_model", [](const CalibratedModel& c) { return c.surface.has_value(); },
          "True for the Arnab & Raja surface model")
      .def("__repr__", [](const CalibratedModel& c) {
        return "<hooke.Model " + c.method + ", " + std::to_string(c.mesh.node_count()) + " nodes, " +
               std::to_string(c.springs.pairs.size()) + " springs>";
      });
}

}  // namespace hooke::python
