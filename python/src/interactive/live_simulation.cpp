// hooke.LiveSimulation: the viewer's physics (interactive::LiveSimulation) from Python, e.g. for a haptic device's
// loop: a model, the clamp, a probe that grabs and drives nodes, settings changed while it runs; and
// hooke.fem_probe_equilibrium, the FEM reference under the same probe.
#include <pybind11/stl.h>
#include <bindings.hpp>
#include <core/arrays.hpp>
#include <hooke/interactive/live_simulation.hpp>
#include <hooke/interactive/physics_loop.hpp>

namespace py = pybind11;

namespace hooke::python {
namespace {

py::list as_list(const VecX& v) {
  py::list out;
  for (Eigen::Index i = 0; i < v.size(); ++i) out.append(v(i));
  return out;
}

// Applies keyword settings as a script's `set` command would (interactive::apply_setting), plus method.
interactive::LiveSettings with_settings(interactive::LiveSettings s, const py::kwargs& kwargs) {
  for (const auto& [key, value] : kwargs) {
    std::string name = py::str(key);
    for (char& c : name)
      if (c == '_') c = '-';
    std::string text =
        py::isinstance<py::bool_>(value) ? (value.cast<bool>() ? "on" : "off") : std::string(py::str(value));
    interactive::apply_setting(s, name, text);
  }
  return s;
}

}  // namespace

void define_live_simulation(py::module_& m) {
  using interactive::LiveSimulation;
  const auto dim = [](const LiveSimulation& s) { return s.model().mesh.dim(); };
  const auto positions = [](LiveSimulation& s) -> const VecX& { return s.positions(); };
  const auto velocities = [](LiveSimulation& s) -> const VecX& { return s.velocities(); };
  py::class_<LiveSimulation>(m, "LiveSimulation",
                             "The viewer's physics: a model run in real time by its caller, the bottom clamped (the "
                             "surface model: held by its anchors), a probe that grabs and drives nodes, settings "
                             "changed while it runs.")
      .def(py::init([](const calibrate::CalibratedModel& model, const std::string& integrator, double dt,
                       const py::kwargs& kwargs) {
             interactive::LiveSettings s;
             s.method = "file";
             s.material = model.material;
             s.density = model.density;
             s.simulator.integrator = solve::integrator_from_name(integrator);
             s.dt = dt;
             return LiveSimulation(model, with_settings(s, kwargs));
           }),
           py::arg("model"), py::arg("integrator") = "quasi-newton", py::arg("dt") = 1e-3,
           "LiveSimulation(model, integrator='quasi-newton', dt=1e-3, **settings): settings as in the viewer's "
           "scripts (gravity=True, damping_mass=..., damping_stiffness=..., young=..., poisson=..., method=...).")
      .def(
          "apply", [](LiveSimulation& s, const py::kwargs& kwargs) { s.apply(with_settings(s.settings(), kwargs)); },
          "apply(**settings): e.g. apply(poisson=0.45) recalibrates; the deformation and the grab are kept; when it "
          "fails nothing changes.")
      .def(
          "step",
          [](LiveSimulation& s) {
            py::gil_scoped_release release;
            return s.step();
          },
          "One step of dt seconds; returns its StepReport. Raises SolverFailure when it inverts an element.")
      .def("reset", &LiveSimulation::reset, "Back to rest, time 0, probe released.")
      .def("grab", &LiveSimulation::grab, py::arg("nodes"), "Grabs nodes where they are.")
      .def(
          "drag",
          [](LiveSimulation& s, const py::object& offset) {
            s.drag(vector_argument(offset, "offset", s.model().mesh.dim()));
          },
          py::arg("offset"), "Drives the grabbed nodes to their grab positions + offset (m, dim).")
      .def("release", &LiveSimulation::release, "Lets go.")
      .def_property_readonly(
          "probe_force", [](const LiveSimulation& s) { return as_list(s.probe_force()); },
          "the force the body exerts on the probe after the last step, N (dim)")
      .def_property_readonly("time", &LiveSimulation::time, "simulated time, s")
      .def_property_readonly("positions", rows_property<LiveSimulation>(positions, dim),
                             "(N, dim) node positions, m (read-only view)")
      .def_property_readonly("velocities", rows_property<LiveSimulation>(velocities, dim),
                             "(N, dim) node velocities, m/s (read-only view)")
      .def_property_readonly("model", &LiveSimulation::model, "the model being simulated (a copy)")
      .def_property_readonly("clamped_nodes", &LiveSimulation::clamped_nodes, "the nodes held at rest")
      .def_property_readonly("grabbed", &LiveSimulation::grabbed, "the grabbed nodes");
  m.def(
      "fem_probe_equilibrium",
      [](const calibrate::CalibratedModel& model, const std::string& law, const std::vector<int>& clamped,
         const std::vector<int>& grabbed, const py::object& targets, bool gravity) {
        const VecX t =
            vector_argument(targets, "targets", model.mesh.dim() * static_cast<Eigen::Index>(grabbed.size()));
        interactive::ProbeEquilibrium r;
        {
          py::gil_scoped_release release;
          r = interactive::fem_probe_equilibrium(model, material::law_from_name(law), clamped, grabbed, t, gravity);
        }
        const py::ssize_t d = model.mesh.dim(), n = r.positions.size() / d;
        py::array_t<double> x({n, d});
        std::copy(r.positions.data(), r.positions.data() + r.positions.size(), x.mutable_data());
        return py::make_tuple(x, as_list(r.holding_force));
      },
      py::arg("model"), py::arg("law"), py::arg("clamped"), py::arg("grabbed"), py::arg("targets"),
      py::arg("gravity") = false,
      "The FEM (law 'linear' or 'stvk') static equilibrium on model's mesh with `clamped` nodes at rest and "
      "`grabbed` nodes held at `targets` ((len(grabbed) * dim,) m): (positions (N, dim) m, holding force N) - what "
      "the viewer's FEM ghost shows.");
}

}  // namespace hooke::python
