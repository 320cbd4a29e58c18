// Statics: hooke.Problem (a model, held nodes, loads, an interaction) and hooke.static_equilibrium /
// linear_static with their SolveReport; the linearised stiffness as CSR arrays (scipy.sparse in hooke/).
#include <pybind11/stl.h>
#include <bindings.hpp>
#include <core/arrays.hpp>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/model/load_case.hpp>
#include <solve/problem.hpp>
#include <solve/reports.hpp>

namespace py = pybind11;

namespace hooke::python {

void define_reports(py::module_& m) {
  py::class_<solve::SolveReport>(m, "SolveReport", "What a static solve did (numbers, never exceptions).")
      .def_property_readonly(
          "status", [](const solve::SolveReport& r) { return std::string(solve::status_name(r.status)); },
          "'converged', 'not-converged', 'unstable' or 'singular'")
      .def_readonly("iterations", &solve::SolveReport::iterations, "Newton iterations over all load steps")
      .def_readonly("load_steps", &solve::SolveReport::load_steps, "accepted load steps")
      .def_readonly("load_factor", &solve::SolveReport::load_factor,
                    "load factor of the returned state (1 = full load)")
      .def_readonly("residual", &solve::SolveReport::residual, "free-DOF force residual, N")
      .def_readonly("reference_force", &solve::SolveReport::reference_force, "norm of the applied forces, N")
      .def_readonly("min_eigenvalue", &solve::SolveReport::min_eigenvalue, "smallest tangent eigenvalue, N/m")
      .def_readonly("critical_load_factor", &solve::SolveReport::critical_load_factor,
                    "load factor where stability is lost, or -1")
      .def_readonly("free_dofs", &solve::SolveReport::free_dofs, "number of unknowns")
      .def_readonly("solve_seconds", &solve::SolveReport::solve_seconds, "wall time, s")
      .def_readonly("backend", &solve::SolveReport::backend, "linear solver used")
      .def_readonly("residual_history", &solve::SolveReport::residual_history, "residual per Newton iteration, N")
      .def_readonly("message", &solve::SolveReport::message, "one sentence on the outcome")
      .def_property_readonly(
          "converged", [](const solve::SolveReport& r) { return r.status == solve::SolveStatus::kConverged; },
          "status == \'converged\'")
      .def("__repr__", [](const solve::SolveReport& r) {
        return "<hooke.SolveReport " + std::string(solve::status_name(r.status)) + ": " + r.message + ">";
      });
}

void raise_unless_converged(const solve::SolveReport& report) {
  if (report.status == solve::SolveStatus::kConverged) return;
  const py::object type = py::module_::import("hooke._hooke").attr("SolverFailure");
  py::object error = type(report.message);
  error.attr("report") = report;
  PyErr_SetObject(type.ptr(), error.ptr());
  throw py::error_already_set();
}

void define_static_equilibrium(py::module_& m) {
  define_reports(m);
  py::class_<ProblemData>(m, "Problem",
                          "A model with held nodes, dead loads and (for the surface model) an interaction.")
      .def(py::init([](const calibrate::CalibratedModel& model) { return ProblemData(model); }), py::arg("model"),
           "Problem(model): every node free, no load.")
      .def(
          "fix_nodes", [](ProblemData& p, const std::vector<int>& nodes) { p.fix_nodes(nodes); }, py::arg("nodes"),
          "Holds the nodes at their rest positions.")
      .def(
          "add_tool",
          [](ProblemData& p, const std::string& shape, const py::object& position, const py::object& rotation,
             double contact_distance, double friction, double slip) {
            contact::Pose pose;
            pose.position = vector_argument(position, "position", 3);
            if (!rotation.is_none()) pose.rotation = matrix_argument(rotation, "rotation", 3, 3);
            return p.add_tool(shape, pose, contact_distance, {friction, slip});
          },
          py::arg("shape"), py::arg("position"), py::arg("rotation") = py::none(), py::arg("contact_distance") = 0.0,
          py::arg("friction") = 0.0, py::arg("slip") = 0.0,
          "A rigid tool against the body's boundary (docs/contact.md): shape 'sphere:R', 'capsule:R,L' (m) or "
          "'plane', at position (3,) m with rotation (3, 3) (None: identity; a plane's outward normal and a capsule's "
          "axis are its z). contact_distance: the barrier's activation distance, m (0: 1 % of the mean boundary "
          "edge). friction: Coulomb coefficient (>= 0); slip: the slip per step (or per press pose) below which "
          "friction "
          "acts as a stiff spring, m (0: 1e-5 of the body's bounding-box diagonal). 'plane' makes an obstacle the "
          "body rests on. Returns a hooke.Tool. Simulators and solves made after this call see the tool.")
      .def(
          "apply_load",
          [](ProblemData& p, const std::string& kind, const py::object& traction, const py::object& strain) {
            if (traction.is_none() == strain.is_none())
              throw py::value_error("apply_load: give exactly one of traction (Pa) and strain");
            p.apply_load(model::load_kind_from_name(kind), traction.is_none() ? 0.0 : traction.cast<double>(),
                         strain.is_none() ? 0.0 : strain.cast<double>());
          },
          py::arg("kind"), py::arg("traction") = py::none(), py::arg("strain") = py::none(),
          "The paper's load cases: 'stretch', 'compress' or 'shear' on the top face (max z, max y in 2D), the bottom "
          "clamped; `traction` in Pa, or `strain` = the mean top strain of the linear FEM.")
      .def_property(
          "external_force",
          [](py::object self) {
            auto& p = self.cast<ProblemData&>();
            return flat_view(p.problem.external_force.data(), p.problem.external_force.size(), self, true);
          },
          [](ProblemData& p, const py::object& f) {
            p.problem.external_force = vector_argument(f, "external_force", p.problem.model->dof_count());
          },
          "(dim * N,) dead nodal forces, N (a writable view).")
      .def_property_readonly(
          "fixed_dofs",
          [](const ProblemData& p) {
            std::vector<int> fixed;
            for (size_t i = 0; i < p.problem.fixed_dofs.size(); ++i)
              if (p.problem.fixed_dofs[i]) fixed.push_back(static_cast<int>(i));
            return fixed;
          },
          "indices of the held DOFs (dim * node + axis)")
      .def(
          "set_interaction",
          [](ProblemData& p, const py::object& point, const py::object& direction, double radius) {
            model::Interaction in{vector_argument(point, "point", 3), vector_argument(direction, "direction", 3),
                                  radius};
            model::require_valid(in);
            p.problem.interaction = in;
          },
          py::arg("point"), py::arg("direction"), py::arg("radius"),
          "Where a probe pushes (m, a direction, radius m): the surface model's Eq. 4 weights follow it.")
      .def(
          "stiffness_csr",
          [](const ProblemData& p) {
            const SparseMatrix k =
                p.problem.model->hessian(p.problem.model->rest_positions(), false, p.problem.interaction_or_null());
            // Symmetric: its compressed columns are the compressed rows of the same matrix.
            py::array_t<double> data(k.nonZeros());
            py::array_t<int> indices(k.nonZeros()), indptr(k.outerSize() + 1);
            std::copy(k.valuePtr(), k.valuePtr() + k.nonZeros(), data.mutable_data());
            std::copy(k.innerIndexPtr(), k.innerIndexPtr() + k.nonZeros(), indices.mutable_data());
            std::copy(k.outerIndexPtr(), k.outerIndexPtr() + k.outerSize() + 1, indptr.mutable_data());
            return py::make_tuple(data, indices, indptr, py::make_tuple(k.rows(), k.cols()));
          },
          "(data, indices, indptr, shape) of the model's Hessian at rest, N/m (use hooke.stiffness for scipy).");

  m.def(
      "static_equilibrium",
      [](const ProblemData& p, int max_iterations, double tolerance, bool check_stability, bool raise_on_failure) {
        solve::StaticOptions o;
        o.newton.max_iterations = max_iterations;
        o.newton.tolerance = tolerance;
        o.check_stability = check_stability;
        solve::StaticResult r;
        {
          py::gil_scoped_release release;
          r = solve::static_equilibrium(p.problem, o);
        }
        if (raise_on_failure) raise_unless_converged(r.report);
        return py::make_tuple(p.rows(r.positions), r.report);
      },
      py::arg("problem"), py::arg("max_iterations") = 40, py::arg("tolerance") = 1e-9,
      py::arg("check_stability") = true, py::arg("raise_on_failure") = true,
      "Newton with line search and load stepping to the stable static equilibrium. Returns (positions (N, dim) in "
      "m, SolveReport); raises SolverFailure (with .report) unless it converged, or raise_on_failure=False.");
  m.def(
      "linear_static",
      [](const ProblemData& p, bool raise_on_failure) {
        solve::StaticResult r;
        {
          py::gil_scoped_release release;
          r = solve::linear_static(p.problem);
        }
        if (raise_on_failure) raise_unless_converged(r.report);
        return py::make_tuple(p.rows(r.positions), r.report);
      },
      py::arg("problem"), py::arg("raise_on_failure") = true,
      "One linear solve K u = f with K the Hessian at rest. Returns (positions (N, dim), SolveReport).");
}

}  // namespace hooke::python
