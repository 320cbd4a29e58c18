#pragma once
/// A named data array attached to the nodes or elements of a mesh (displacement, error, stiffness, ...).
#include <filesystem>
#include <hooke/core/types.hpp>
#include <string>

namespace hooke::io {

struct Field {
  std::string name;    ///< shown in ParaView
  int components = 1;  ///< values per node or element (1 scalar, 3 vector; 2D vectors are padded to 3 in VTU)
  VecX values;         ///< flat, entity-major: values[components * i + c]
};

/// Writers call this before opening a file: no file hooke writes holds inf or NaN.
/// @throws NonFiniteResult naming `file`, the field and the first entity with a non-finite value
void require_finite(const Field& field, const std::filesystem::path& file);
/// The same for node positions (#V x dim rows, m).
void require_finite_positions(const RowMatX& nodes, const std::filesystem::path& file);

}  // namespace hooke::io
