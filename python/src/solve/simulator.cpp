// Dynamics: hooke.Simulator over a Problem, with positions / velocities as zero-copy read-only views, the probe
// (grab, drive, push, release, probe_force), and the GIL released inside step().
#include <pybind11/stl.h>

#include <algorithm>
#include <bindings.hpp>
#include <chrono>
#include <core/arrays.hpp>
#include <hooke/solve/simulator.hpp>
#include <hooke/solve/simulator_settings.hpp>
#include <hooke/solve/tool_press.hpp>
#include <optional>
#include <solve/problem.hpp>

namespace py = pybind11;

namespace hooke::python {
namespace {

struct PySimulator {
  solve::Simulator sim;
  solve::Probe probe;
  solve::StepReport last;
  int dim;
};

}  // namespace

void define_simulator(py::module_& m) {
  py::class_<solve::StepReport>(m, "StepReport", "What one time step did.")
      .def_readonly("iterations", &solve::StepReport::iterations, "Newton or local/global iterations")
      .def_readonly("linear_iterations", &solve::StepReport::linear_iterations, "CG iterations (cg only)")
      .def_readonly("residual", &solve::StepReport::residual, "|gradient of the step's objective|, N")
      .def_readonly("converged", &solve::StepReport::converged, "False when Newton ended above its tolerance")
      .def_readonly("beyond_stable_dt", &solve::StepReport::beyond_stable_dt, "explicit steps: dt above the limit")
      .def_property_readonly(
          "probe_force",
          [](const solve::StepReport& r) {
            return std::vector<double>(r.probe_force.data(), r.probe_force.data() + r.probe_force.size());
          },
          "the force the body exerts on the probe, N (dim)");
  const auto dim = [](const PySimulator& s) { return s.dim; };
  const auto positions = [](PySimulator& s) -> const VecX& { return s.sim.positions(); };
  const auto velocities = [](PySimulator& s) -> const VecX& { return s.sim.velocities(); };
  py::class_<PySimulator>(m, "Simulator", "Steps a Problem in time (solve::Simulator).")
      .def(py::init([](const ProblemData& p, const std::string& integrator, const py::object& gravity,
                       double damping_mass, double damping_stiffness, const py::kwargs& settings) {
             solve::SimulatorOptions o;
             o.integrator = solve::integrator_from_name(integrator);
             for (const auto& [key, value] : settings) {  // solve::simulator_fields(), dashes as underscores
               std::string name = py::str(key);
               std::replace(name.begin(), name.end(), '_', '-');
               if (!solve::set_simulator_field(o, name, std::string(py::str(value))))
                 throw py::type_error("Simulator: unknown setting '" + std::string(py::str(key)) + "'");
             }
             const int d = p.problem.model->dim();
             solve::Dynamics dyn{p.model.masses, gravity.is_none() ? VecX() : vector_argument(gravity, "gravity", d),
                                 damping_mass, damping_stiffness};
             return new PySimulator{solve::Simulator(p.problem, dyn, o), {}, {}, d};
           }),
           py::arg("problem"), py::arg("integrator") = "quasi-newton", py::arg("gravity") = py::none(),
           py::arg("damping_mass") = 0.0, py::arg("damping_stiffness") = 0.0,
           "Simulator(problem, integrator='quasi-newton', gravity=None, damping_mass=0, damping_stiffness=0, "
           "**settings): integrator one of quasi-newton (every model, at most qn_iterations L-BFGS iterations per "
           "step), symplectic-euler, velocity-verlet, implicit-euler, implicit-euler-linearised, local-global "
           "(springs only), quasi-static; masses from the model; gravity (dim,) in m/s^2; Rayleigh damping alpha "
           "(1/s) and beta (s). settings: the integrator's options as `hooke simulate` takes them, dashes as "
           "underscores: qn_iterations, qn_tolerance, qn_hessian, linear_solver, cg_tolerance, newton_tolerance, "
           "newton_iterations, global_solve, iterations.")
      .def(
          "step",
          [](PySimulator& s, double dt) {
            {
              py::gil_scoped_release release;
              s.last = s.sim.step(dt);
            }
            return s.last;
          },
          py::arg("dt"),
          "Advances by dt seconds; returns the step's report (iterations, residual N, converged, probe_force N).")
      .def(
          "run",
          [](PySimulator& s, int steps, double dt) {
            std::vector<double> ms(static_cast<size_t>(std::max(steps, 0)));
            {
              py::gil_scoped_release release;
              for (auto& t : ms) {
                const auto t0 = std::chrono::steady_clock::now();
                s.last = s.sim.step(dt);
                t = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
              }
            }
            return ms;
          },
          py::arg("steps"), py::arg("dt"), "Runs `steps` steps in C++; returns each step's wall time, ms.")
      .def_property_readonly("positions", rows_property<PySimulator>(positions, dim),
                             "(N, dim) positions, m: a read-only view of the simulator's state (no copy; changes as it "
                             "steps).")
      .def_property_readonly("velocities", rows_property<PySimulator>(velocities, dim),
                             "(N, dim) velocities, m/s: a read-only view.")
      .def_property_readonly(
          "time", [](const PySimulator& s) { return s.sim.time(); }, "s")
      .def(
          "move_tool",
          [](PySimulator& s, PyTool& t, const py::object& position, const py::object& rotation) {
            contact::Pose pose;
            pose.position = vector_argument(position, "position", 3);
            pose.rotation =
                rotation.is_none() ? t.tool->pose().rotation : Mat3(matrix_argument(rotation, "rotation", 3, 3));
            return solve::move_tool(s.sim, *t.block, *t.tool, pose);
          },
          py::arg("tool"), py::arg("position"), py::arg("rotation") = py::none(),
          "Moves a tool of the simulator's problem to `position` (m; `rotation` (3, 3) or None: kept) between steps, "
          "putting back outside it the nodes it passed; returns how many (solve::move_tool). The tool must have been "
          "added to the problem before this simulator was made.")
      .def(
          "grab",
          [](PySimulator& s, const std::vector<int>& nodes) {
            s.probe = solve::Probe{nodes, true, VecX::Zero(s.dim), VecX::Zero(s.dim)};
            s.sim.set_probe(s.probe);
          },
          py::arg("nodes"), "Grabs the nodes where they are now (as a haptic device would).")
      .def(
          "drive",
          [](PySimulator& s, const py::object& offset) {
            s.probe.drive_position = true;
            s.probe.offset = vector_argument(offset, "offset", s.dim);
            s.sim.set_probe(s.probe);
          },
          py::arg("offset"), "Drives the grabbed nodes to grab position + offset (m).")
      .def(
          "push",
          [](PySimulator& s, const py::object& force) {
            s.probe.drive_position = false;
            s.probe.force = vector_argument(force, "force", s.dim);
            s.sim.set_probe(s.probe);
          },
          py::arg("force"), "Pushes the grabbed nodes with a total force (N) instead of driving them.")
      .def(
          "release",
          [](PySimulator& s) {
            s.sim.set_probe(solve::Probe{});
            s.probe = {};
          },
          "Lets go.")
      .def_property_readonly(
          "probe_force",
          [](const PySimulator& s) {
            return std::vector<double>(s.last.probe_force.data(),
                                       s.last.probe_force.data() + s.last.probe_force.size());
          },
          "The force the body exerted on the probe at the end of the last step, N (what a haptic device renders).")
      .def(
          "kinetic_energy", [](const PySimulator& s) { return s.sim.kinetic_energy(); }, "J")
      .def(
          "potential_energy", [](const PySimulator& s) { return s.sim.potential_energy(); }, "J")
      .def(
          "stable_time_step", [](const PySimulator& s) { return s.sim.stable_time_step(); },
          "Explicit stability limit, s.");
}

}  // namespace hooke::python
