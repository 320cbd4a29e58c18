// hooke.LiveSimulation: the viewer's physics (interactive::LiveSimulation) from Python, e.g. for a haptic device's
// loop: a model, the clamp, a probe that grabs and drives nodes, settings changed while it runs; and
// hooke.fem_probe_equilibrium, the FEM reference under the same probe.
#include <pybind11/stl.h>
#include <bindings.hpp>
#include <contact/tool.hpp>
#include <core/arrays.hpp>
#include <hooke/interactive/guarded.hpp>
#include <hooke/interactive/live_simulation.hpp>
#include <hooke/interactive/physics_loop.hpp>
#include <utility>

namespace py = pybind11;

namespace hooke::python {
namespace {

// A copy of m as a (rows, cols) array.
py::array_t<double> as_array(const MatX& m) {
  py::array_t<double> a({m.rows(), m.cols()});
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) a.mutable_at(i, j) = m(i, j);
  return a;
}

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

// hooke.LiveSimulation: the simulation behind one lock, so that a device thread may drag while another steps
// (step() releases the GIL). Every getter returns a copy: the simulator's arrays are replaced by reset() and
// apply(), so a view of them would dangle.
using SharedSimulation = interactive::Guarded<interactive::LiveSimulation>;

// f(simulation) under the lock, without the GIL (a thread stepping holds the lock, not the GIL).
template <typename F>
auto locked(SharedSimulation& s, F&& f) {
  py::gil_scoped_release release;
  return s.with(std::forward<F>(f));
}

// A property getter: a copy of the flat state vector `field` picks, as (N, dim) rows.
auto state_rows(const VecX& (interactive::LiveSimulation::*field)() const) {
  return [field](SharedSimulation& s) {
    const auto [v, dim] = locked(s, [field](const interactive::LiveSimulation& sim) {
      return std::pair((sim.*field)(), sim.model().mesh.dim());
    });
    const py::ssize_t d = dim, n = v.size() / dim;
    py::array_t<double> a({n, d});
    std::copy(v.data(), v.data() + v.size(), a.mutable_data());
    return a;
  };
}

}  // namespace

void define_live_simulation(py::module_& m) {
  using interactive::LiveSimulation;
  using Sim = LiveSimulation;
  py::class_<SharedSimulation>(m, "LiveSimulation",
                               "The viewer's physics: a model run in real time by its caller, the bottom clamped (the "
                               "surface model: held by its anchors), a probe that grabs and drives nodes, settings "
                               "changed while it runs. Thread-safe: one thread may step while another drags; every "
                               "property is a copy.")
      .def(py::init([](const calibrate::CalibratedModel& model, const std::string& integrator, double dt,
                       const py::kwargs& kwargs) {
             interactive::LiveSettings s;
             s.model.method = interactive::live_method_for(model);
             s.material = model.material;
             s.model.density = model.density;
             s.model.regions = model.regions;
             s.simulator.integrator = solve::integrator_from_name(integrator);
             s.dynamics.dt = dt;
             return std::make_unique<SharedSimulation>(LiveSimulation(model, with_settings(s, kwargs)));
           }),
           py::arg("model"), py::arg("integrator") = "quasi-newton", py::arg("dt") = 1e-3,
           "LiveSimulation(model, integrator='quasi-newton', dt=1e-3, **settings): settings as in the viewer's "
           "scripts (gravity=True, damping_mass=..., damping_stiffness=..., young=..., poisson=..., method=...).")
      .def(
          "apply",
          [](SharedSimulation& s, const py::kwargs& kwargs) {
            const interactive::LiveSettings current = locked(s, [](const Sim& sim) { return sim.settings(); });
            const interactive::LiveSettings next = with_settings(current, kwargs);
            locked(s, [&](Sim& sim) { sim.apply(next); });
          },
          "apply(**settings): e.g. apply(poisson=0.45) recalibrates; the deformation and the grab are kept; when it "
          "fails nothing changes.")
      .def(
          "step", [](SharedSimulation& s) { return locked(s, [](Sim& sim) { return sim.step(); }); },
          "One step of dt seconds; returns its StepReport. Raises SolverFailure when it inverts an element.")
      .def(
          "reset", [](SharedSimulation& s) { locked(s, [](Sim& sim) { sim.reset(); }); },
          "Back to rest, time 0, probe released.")
      .def(
          "grab",
          [](SharedSimulation& s, const std::vector<int>& nodes) { locked(s, [&](Sim& sim) { sim.grab(nodes); }); },
          py::arg("nodes"), "Grabs nodes where they are.")
      .def(
          "drag",
          [](SharedSimulation& s, const py::object& offset) {
            const int d = locked(s, [](const Sim& sim) { return sim.model().mesh.dim(); });
            const VecX u = vector_argument(offset, "offset", d);
            locked(s, [&](Sim& sim) { sim.drag(u); });
          },
          py::arg("offset"), "Drives the grabbed nodes to their grab positions + offset (m, dim).")
      .def(
          "release", [](SharedSimulation& s) { locked(s, [](Sim& sim) { sim.release(); }); }, "Lets go.")
      .def(
          "set_tool",
          [](SharedSimulation& s, const std::string& shape, const py::object& position, const py::object& rotation,
             double friction) {
            const contact::Pose pose = pose_argument(position, rotation);
            locked(s, [&](Sim& sim) { sim.set_tool(shape, pose, friction); });
          },
          py::arg("shape"), py::arg("position"), py::arg("rotation") = py::none(), py::arg("friction") = 0.0,
          "Puts a rigid tool ('sphere:R', 'capsule:R,L', 'mesh:FILE'; m) at position (m) against the body, with "
          "Coulomb friction; nodes inside it are put outside. Without a grab, haptic_model() then carries its local "
          "contact model and a device drives it with drive_tool (docs/contact.md).")
      .def(
          "move_tool",
          [](SharedSimulation& s, const py::object& position, const py::object& rotation) {
            const contact::Pose pose = pose_argument(position, rotation);
            locked(s, [&](Sim& sim) { sim.move_tool(pose); });
          },
          py::arg("position"), py::arg("rotation") = py::none(), "Moves the tool before the next step.")
      .def(
          "drive_tool",
          [](SharedSimulation& s, const py::object& offset) {
            const VecX u = vector_argument(offset, "offset", 3);
            locked(s, [&](Sim& sim) { sim.drive_tool(u); });
          },
          py::arg("offset"), "Moves the tool to where set_tool put it + offset (m, 3): a haptic device's position.")
      .def(
          "remove_tool", [](SharedSimulation& s) { locked(s, [](Sim& sim) { sim.remove_tool(); }); },
          "Takes the tool away.")
      .def_property_readonly(
          "tool_force",
          [](SharedSimulation& s) {
            return as_list(locked(s, [](const Sim& sim) { return sim.tool() ? VecX(sim.tool()->force) : VecX(); }));
          },
          "the force the body exerts on the tool after the last step, N (3; empty without a tool)")
      .def_property_readonly(
          "probe_force",
          [](SharedSimulation& s) { return as_list(locked(s, [](const Sim& sim) { return sim.probe_force(); })); },
          "the force the body exerts on the probe after the last step, N (dim)")
      .def(
          "haptic_model", [](SharedSimulation& s) { return locked(s, [](Sim& sim) { return sim.haptic_model(); }); },
          "The probe's local model after the last step (HapticModel): a haptic device's own 1 kHz loop renders "
          "model.render(offset) between two steps (multirate haptics).")
      .def(
          "set_local_model_in_background",
          [](SharedSimulation& s, bool background) {
            locked(s, [&](Sim& sim) { sim.set_local_model_in_background(background); });
          },
          py::arg("background"),
          "True: the grab's local model (condensed stiffness and curvature) is made in a thread of its own, the steps "
          "going on and haptic_model() holding the force until it is there (as the viewer's real-time loop does); "
          "False (the default): made at the first call after a grab, the same every run.")
      .def_property_readonly(
          "time", [](SharedSimulation& s) { return locked(s, [](const Sim& sim) { return sim.time(); }); },
          "simulated time, s")
      .def_property_readonly("positions", state_rows(&Sim::positions), "(N, dim) node positions, m (a copy)")
      .def_property_readonly("velocities", state_rows(&Sim::velocities), "(N, dim) node velocities, m/s (a copy)")
      .def_property_readonly(
          "model", [](SharedSimulation& s) { return locked(s, [](const Sim& sim) { return sim.model(); }); },
          "the model being simulated (a copy)")
      .def_property_readonly(
          "clamped_nodes",
          [](SharedSimulation& s) { return locked(s, [](const Sim& sim) { return sim.clamped_nodes(); }); },
          "the nodes held at rest")
      .def_property_readonly(
          "grabbed", [](SharedSimulation& s) { return locked(s, [](const Sim& sim) { return sim.grabbed(); }); },
          "the grabbed nodes");
  py::class_<interactive::HapticModel>(m, "HapticModel",
                                       "The probe's local model after a deformation step: force(u) = force - "
                                       "stiffness d - curvature (d, d) / 2, d = u - offset.")
      .def_readonly("version", &interactive::HapticModel::version, "increases with every deformation step")
      .def_readonly("time", &interactive::HapticModel::time, "simulated time at the end of the step, s")
      .def_readonly("grabbed", &interactive::HapticModel::grabbed, "the probe holds nodes")
      .def_property_readonly(
          "offset", [](const interactive::HapticModel& h) { return as_list(h.offset); }, "the step's offset, m")
      .def_property_readonly(
          "force", [](const interactive::HapticModel& h) { return as_list(h.force); }, "the force after it, N")
      .def_property_readonly(
          "stiffness", [](const interactive::HapticModel& h) { return as_array(h.stiffness); },
          "the local stiffness, N/m (dim x dim)")
      .def_property_readonly(
          "curvature", [](const interactive::HapticModel& h) { return as_array(h.curvature); },
          "the condensed energy's third derivative at the grab, N/m^2 (dim x dim^2: T[c, a dim + b]; 0 x 0 when "
          "the model is linear, haptic_curvature=False)")
      .def_readonly("tool", &interactive::HapticModel::tool,
                    "a tool without a grab: offset and force are the tool's (from where set_tool put it)")
      .def_property_readonly(
          "contact_nodes", [](const interactive::HapticModel& h) { return h.contact ? h.contact->node_count() : 0; },
          "the surface nodes of the tool's local contact model (0: none)")
      .def(
          "render",
          [](const interactive::HapticModel& h, const py::object& u) {
            const VecX offset = vector_argument(u, "offset", h.offset.size());
            VecX f;
            {
              py::gil_scoped_release release;
              f = h.render(offset);
            }
            return as_list(f);
          },
          py::arg("offset"),
          "The force on the probe, or on the tool, at the device's `offset` (m, dim), N: the local model's (a "
          "tool's from its local contact model, docs/contact.md).");
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
