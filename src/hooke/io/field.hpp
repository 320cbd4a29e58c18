#pragma once
/// A named data array attached to the nodes or elements of a mesh (displacement, error, stiffness, ...).
#include <hooke/core/types.hpp>
#include <string>

namespace hooke::io {

struct Field {
  std::string name;    ///< shown in ParaView
  int components = 1;  ///< values per node or element (1 scalar, 3 vector; 2D vectors are padded to 3 in VTU)
  VecX values;         ///< flat, entity-major: values[components * i + c]
};

}  // namespace hooke::io
