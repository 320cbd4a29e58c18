// hooke.compare: a calibrated model against the FEM reference under one load case, both displacement fields and
// the node errors; hooke.compare_under_contact: the same under a pressing tool, depth by depth.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>
#include <bindings.hpp>
#include <calibrate/calibrated_model.hpp>
#include <core/arrays.hpp>
#include <hooke/contact/rigid_tool.hpp>
#include <hooke/experiments/compare.hpp>
#include <hooke/experiments/contact_comparison.hpp>

namespace py = pybind11;

namespace hooke::python {

void define_compare(py::module_& m) {
  using experiments::Comparison;
  const auto dim = [](const Comparison& c) { return c.fem_mesh.dim(); };
  const auto fem = [](Comparison& c) -> VecX& { return c.fem_positions; };
  const auto model_x = [](Comparison& c) -> VecX& { return c.spring_positions; };
  const auto error = [](Comparison& c) -> VecX& { return c.node_error; };
  py::class_<Comparison>(m, "Comparison", "A model's static answer beside the FEM reference's.")
      .def_property_readonly("fem_positions", rows_property<Comparison>(fem, dim),
                             "(N, dim) FEM equilibrium at the model's nodes, m")
      .def_property_readonly("model_positions", rows_property<Comparison>(model_x, dim),
                             "(N, dim) the model's equilibrium, m")
      .def_property_readonly("node_error", flat_property<Comparison>(error, false),
                             "(N,) |x_model - x_fem| per node, m")
      .def_readonly("max_error", &Comparison::max_error, "m")
      .def_readonly("mean_error", &Comparison::mean_error, "m")
      .def_readonly("relative_l2", &Comparison::relative_l2, "||x_model - x_fem|| / ||x_fem - X||")
      .def_readonly("fem_report", &Comparison::fem_report, "SolveReport of the FEM reference")
      .def_readonly("model_report", &Comparison::spring_report, "SolveReport of the model")
      .def_property_readonly(
          "traction", [](const Comparison& c) { return c.load.traction_pa; }, "Pa")
      .def_property_readonly(
          "displacement", [](const Comparison& c) { return c.load.displacement; },
          "the top's move under displacement control, m")
      .def_property_readonly(
          "control", [](const Comparison& c) { return std::string(model::load_control_name(c.load.control)); },
          "'traction' or 'displacement'")
      .def_property_readonly(
          "fem_force", [](const Comparison& c) { return c.fem_reaction; },
          "(dim,) total force on the top nodes in the FEM's equilibrium, N")
      .def_property_readonly(
          "model_force", [](const Comparison& c) { return c.spring_reaction; },
          "(dim,) total force on the top nodes in the model's equilibrium, N")
      .def_readonly("force_error", &Comparison::reaction_error, "|model_force - fem_force| / |fem_force|");
  m.def(
      "compare",
      [](const calibrate::CalibratedModel& model, const std::string& load, const py::object& strain,
         const py::object& traction, const std::string& reference, int layers, const std::string& control) {
        experiments::CompareOptions o;
        o.load = model::load_kind_from_name(load);
        o.reference = material::law_from_name(reference);
        o.control = model::load_control_from_name(control);
        if (o.control == model::LoadControl::kDisplacement && strain.is_none())
          throw py::value_error("compare: displacement control needs strain (the top moved by strain x height)");
        if (strain.is_none() == traction.is_none())
          throw py::value_error("compare: give exactly one of strain and traction (Pa)");
        if (!strain.is_none()) o.strain = strain.cast<double>();
        if (!traction.is_none()) o.traction_pa = traction.cast<double>();
        if (!(o.strain > 0.0 || o.traction_pa > 0.0) || !std::isfinite(o.strain) || !std::isfinite(o.traction_pa))
          throw py::value_error("compare: the strain or traction must be a finite number > 0");
        py::gil_scoped_release release;
        return experiments::compare_calibrated(model, o, layers);
      },
      py::arg("model"), py::arg("load") = "stretch", py::arg("strain") = py::none(), py::arg("traction") = py::none(),
      py::arg("reference") = "linear", py::arg("layers") = 4, py::arg("control") = "traction",
      "The model and the FEM (law `reference`: linear, stvk, neohookean) under the load case 'stretch', 'compress' "
      "or 'shear' at mean linear-FEM `strain` or `traction` (Pa), or with control='displacement' the top moved by "
      "strain x height (the forces on it compared: force_error); the surface model against tets of `layers` "
      "layers. Returns a Comparison.");
  m.def(
      "compare_under_contact",
      [](const calibrate::CalibratedModel& model, const std::string& tool, const py::object& position, double depth,
         int steps, const std::string& reference, double contact_distance) {
        experiments::ContactPressOptions o;
        o.start.position = vector_argument(position, "position", 3);
        o.depth = depth;
        o.steps = steps;
        o.reference = material::law_from_name(reference);
        o.contact_distance = contact_distance;
        const contact::RigidTool shape = contact::parse_tool(tool);
        std::vector<experiments::ContactPressRow> rows;
        {
          py::gil_scoped_release release;
          rows = experiments::compare_under_contact(model, shape, o);
        }
        py::list out;
        for (const auto& r : rows)
          out.append(py::dict(py::arg("travel") = r.travel, py::arg("fem_force") = Vec3(r.fem_force),
                              py::arg("model_force") = Vec3(r.model_force), py::arg("force_error") = r.force_error,
                              py::arg("relative_l2") = r.relative_l2, py::arg("fem_contacts") = r.fem_contacts,
                              py::arg("model_contacts") = r.model_contacts, py::arg("smallest_gap") = r.smallest_gap));
        return out;
      },
      py::arg("model"), py::arg("tool"), py::arg("position"), py::arg("depth"), py::arg("steps") = 8,
      py::arg("reference") = "neohookean", py::arg("contact_distance") = 0.0,
      "The model and the FEM of its mesh (law `reference`) with the tool 'sphere:R', 'capsule:R,L' or "
      "'mesh:FILE[,ROUNDING]' (m) moved from `position` (3,) m down -z by `depth` m in `steps` equal steps, both "
      "clamped at the bottom (docs/contact.md): a list of dicts per step with the travel (m), both forces on the "
      "tool (N), the force's relative error, the displacement field's relative L2, the nodes in contact and the "
      "smallest gap (m). SolverFailure where either has no stable equilibrium.");
}

}  // namespace hooke::python
