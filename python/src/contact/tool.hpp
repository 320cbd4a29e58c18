#pragma once
// What a Python hooke.Tool holds: the rigid tool (its pose is set from Python) and the contact block against it,
// which Problem.add_tool also put into the problem's model (docs/contact.md).
#include <pybind11/pybind11.h>

#include <hooke/contact/contact_block.hpp>
#include <memory>

namespace hooke::python {

struct PyTool {
  std::shared_ptr<contact::RigidTool> tool;
  std::shared_ptr<const contact::ContactBlock> block;
  int nodes = 0;  ///< the body's node count (positions passed in have this many rows)
};

/// A pose from Python: `position` (3 numbers, m) and `rotation` (3 x 3, or None: the identity).
/// @throws InvalidArgument naming the argument that is malformed
contact::Pose pose_argument(const pybind11::handle& position, const pybind11::handle& rotation);

}  // namespace hooke::python
