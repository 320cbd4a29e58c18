#pragma once
/// Per-node tables as CSV (one row per node), for spreadsheets and plotting scripts.
#include <filesystem>
#include <hooke/io/field.hpp>
#include <hooke/mesh/mesh.hpp>
#include <vector>

namespace hooke::io {

/// Writes "node,x,y[,z],<field>_<c>..." with one row per node: rest coordinates (m) and point fields.
/// @throws InvalidArgument if a field does not have #V x components values
void write_node_csv(const std::filesystem::path& path, const mesh::Mesh& mesh, const std::vector<Field>& fields);

}  // namespace hooke::io
