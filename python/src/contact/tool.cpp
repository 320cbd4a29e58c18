// Contact with rigid tools from Python: hooke.Tool (made by Problem.add_tool) with its pose, the force and torque on
// it and the gaps at given positions, and hooke.press, the quasi-static press through a list of positions.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <bindings.hpp>
#include <contact/tool.hpp>
#include <core/arrays.hpp>
#include <hooke/solve/tool_press.hpp>
#include <solve/problem.hpp>

namespace py = pybind11;

namespace hooke::python {

contact::Pose pose_argument(const py::handle& position, const py::handle& rotation) {
  contact::Pose pose;
  pose.position = vector_argument(position, "position", 3);
  if (!rotation.is_none()) pose.rotation = matrix_argument(rotation, "rotation", 3, 3);
  return pose;
}

namespace {

VecX flat_positions(const py::handle& positions, Eigen::Index nodes) {
  const RowMatX x = matrix_argument(positions, "positions", nodes, 3);
  return Eigen::Map<const VecX>(x.data(), x.size());
}

}  // namespace

void define_contact(py::module_& m) {
  py::class_<PyTool>(m, "Tool", "A rigid tool pressing a Problem's body (Problem.add_tool; docs/contact.md).")
      .def_property_readonly(
          "shape", [](const PyTool& t) { return t.tool->description(); }, "'sphere:R', 'capsule:R,L' or 'plane' (m)")
      .def_property_readonly(
          "contact_distance", [](const PyTool& t) { return t.block->activation(); },
          "the barrier's activation distance, m: a node touching the tool rests within it")
      .def_property_readonly(
          "position", [](const PyTool& t) { return Vec3(t.tool->pose().position); }, "m")
      .def(
          "set_pose",
          [](PyTool& t, const py::object& position, const py::object& rotation) {
            t.tool->set_pose(pose_argument(position, rotation));
          },
          py::arg("position"), py::arg("rotation") = py::none(),
          "Moves the tool: position (3,) m, rotation (3, 3) or None (unchanged axes: identity). Between steps; "
          "Simulator.move_tool also clears the tool's way.")
      .def(
          "force",
          [](const PyTool& t, const py::object& positions) {
            return Vec3(t.block->tool_force(flat_positions(positions, t.nodes)));
          },
          py::arg("positions"), "The force the body at `positions` ((N, 3) m) exerts on the tool, N (3,).")
      .def(
          "torque",
          [](const PyTool& t, const py::object& positions) {
            return Vec3(t.block->tool_torque(flat_positions(positions, t.nodes)));
          },
          py::arg("positions"), "Its torque about the tool's position, N m (3,).")
      .def(
          "smallest_gap",
          [](const PyTool& t, const py::object& positions) {
            return t.block->smallest_distance(flat_positions(positions, t.nodes));
          },
          py::arg("positions"),
          "The smallest distance of a boundary node to the tool, m (> 0 when nothing entered it).")
      .def(
          "active",
          [](const PyTool& t, const py::object& positions) {
            return t.block->active_count(flat_positions(positions, t.nodes));
          },
          py::arg("positions"), "Boundary nodes within the contact distance.");

  m.def(
      "press",
      [](const ProblemData& p, PyTool& t, const py::object& positions) {
        const RowMatX path = matrix_argument(positions, "positions", -1, 3);
        std::vector<contact::Pose> poses(static_cast<std::size_t>(path.rows()));
        for (Eigen::Index k = 0; k < path.rows(); ++k) {
          poses[static_cast<std::size_t>(k)].position = path.row(k).transpose();
          poses[static_cast<std::size_t>(k)].rotation = t.tool->pose().rotation;
        }
        std::vector<solve::ToolPressStep> steps;
        {
          py::gil_scoped_release release;
          steps = solve::press_quasi_statically(p.problem, *t.block, *t.tool, poses);
        }
        py::list out;
        for (const auto& s : steps)
          out.append(py::dict(py::arg("position") = Vec3(s.pose.position), py::arg("force") = Vec3(s.tool_force),
                              py::arg("active") = s.active, py::arg("smallest_gap") = s.smallest_distance,
                              py::arg("positions") = p.rows(s.positions)));
        return out;
      },
      py::arg("problem"), py::arg("tool"), py::arg("positions"),
      "Moves the tool through `positions` ((K, 3) m, its orientation kept) and solves the static equilibrium at "
      "each: a list of dicts with the tool's position, the force on it (N), the nodes in contact, the smallest gap "
      "(m) and the body's positions ((N, 3) m). SolverFailure naming the position where no equilibrium holds.");
}

}  // namespace hooke::python
