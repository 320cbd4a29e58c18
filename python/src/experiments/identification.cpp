// hooke.identify: a spring model identified from reference deformations (Lloyd et al. 2007, Eq. 1-2), from hooke's
// FEM or from arrays; the pure-Python layer returns the report as a dict.
#include <pybind11/stl.h>
#include <bindings.hpp>
#include <core/arrays.hpp>
#include <hooke/core/error.hpp>
#include <hooke/experiments/identification.hpp>

namespace py = pybind11;

namespace hooke::python {
namespace {

// One reference case from a dict: "displacement" (N, dim) m, "force" (N, dim) N, optional "fixed" (N,) bool,
// "prescribed" (N,) bool, "held_out" bool and "name" str. "fixed" is 1 at supports, "prescribed" 1 where an instrument
// holds the node and "force" is its measured reaction (numbers, like every array argument).
identify::ReferenceCase reference_from_dict(const py::dict& d, const mesh::Mesh& mesh, std::size_t index) {
  const int n = mesh.node_count(), dim = mesh.dim();
  if (!d.contains("displacement") || !d.contains("force"))
    throw py::value_error("identify: reference " + std::to_string(index) + " needs 'displacement' and 'force'");
  const RowMatX u = matrix_argument(d["displacement"], "displacement", n, dim);
  const RowMatX f = matrix_argument(d["force"], "force", n, dim);
  identify::ReferenceCase c;
  c.name = d.contains("name") ? d["name"].cast<std::string>() : "reference " + std::to_string(index + 1);
  c.positions = Eigen::Map<const VecX>(RowMatX(mesh.nodes + u).data(), n * dim);
  c.external_force = Eigen::Map<const VecX>(f.data(), n * dim);
  c.fixed_dofs.assign(static_cast<std::size_t>(n * dim), 0);
  if (d.contains("fixed")) {
    const VecX fixed = vector_argument(d["fixed"], "fixed", n);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < dim; ++k) c.fixed_dofs[static_cast<std::size_t>(dim * i + k)] = fixed(i) != 0.0;
  }
  if (d.contains("prescribed")) {
    const VecX prescribed = vector_argument(d["prescribed"], "prescribed", n);
    c.prescribed_dofs.assign(static_cast<std::size_t>(n * dim), 0);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < dim; ++k) c.prescribed_dofs[static_cast<std::size_t>(dim * i + k)] = prescribed(i) != 0.0;
  }
  c.held_out = d.contains("held_out") && d["held_out"].cast<bool>();
  return c;
}

}  // namespace

void define_identify(py::module_& m) {
  m.def(
      "_identify",
      [](const mesh::Mesh& mesh, const material::Material& material, const std::string& params,
         const std::string& objective, const py::object& references, double strain, int held_out, unsigned seed,
         double regularize, double stiffness_floor, int iterations, const std::string& compare, double density,
         double tolerance, bool negative_volume, const std::string& control) {
        const experiments::NamedIdentifyOptions named{params,     objective, regularize,     stiffness_floor,
                                                      iterations, tolerance, negative_volume};
        // checked before the references are built
        const identify::IdentifyOptions options = experiments::identify_options(named, mesh);
        const std::string analytic = compare == "auto" ? experiments::default_analytic_method(mesh) : compare;
        model::load_control_from_name(control);  // refused before any work
        if (control != "traction" && !references.is_none())
          throw InvalidArgument(
              "identify: control applies to FEM references; a reference dict marks its held nodes "
              "with 'prescribed'");
        std::vector<identify::ReferenceCase> cases;
        if (!references.is_none()) {
          std::size_t k = 0;
          for (const py::handle& r : references) cases.push_back(reference_from_dict(r.cast<py::dict>(), mesh, k++));
        }
        py::gil_scoped_release release;
        if (references.is_none()) {
          experiments::ReferenceLoads loads;
          loads.strain = strain;
          loads.held_out = held_out;
          loads.seed = seed;
          loads.control = model::load_control_from_name(control);
          cases = experiments::fem_reference_cases(mesh, material, loads);
        }
        // FEM references of a nonlinear law: the start is the analytic model with its term law fitted up to `strain`.
        const auto study = experiments::identification_study(mesh, material, cases, options, analytic,
                                                             references.is_none() ? strain : 0.0);
        return std::make_pair(experiments::identified_model(mesh, material, density, study, options),
                              experiments::identification_report_json(study, options));
      },
      py::arg("mesh"), py::arg("material"), py::arg("params"), py::arg("objective"), py::arg("references"),
      py::arg("strain"), py::arg("held_out"), py::arg("seed"), py::arg("regularize"), py::arg("stiffness_floor"),
      py::arg("iterations"), py::arg("compare"), py::arg("density"), py::arg("tolerance"), py::arg("negative_volume"),
      py::arg("control") = "traction");
}

}  // namespace hooke::python
