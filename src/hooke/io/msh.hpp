#pragma once
/// Gmsh MSH files, versions 2.2 and 4.1, ASCII and binary.
#include <filesystem>
#include <hooke/mesh/mesh.hpp>

namespace hooke::io {

enum class MshVersion { kV22, kV41 };

/// Reads an MSH 2.2 or 4.1 file (ASCII or binary, detected from $MeshFormat). Keeps the highest-dimensional
/// elements (tets, else triangles/quads); a mesh whose nodes all have z = 0 becomes planar. The region of an
/// element is its first physical tag (0 without one). Node positions as in the file (no unit scaling).
/// Point and line elements, and unknown sections, are skipped; higher-order elements are rejected.
/// @throws IoError if the file cannot be opened; ParseError{file, line or byte} if it is malformed
mesh::Mesh read_msh(const std::filesystem::path& path);

/// Writes `mesh` as MSH 2.2 or 4.1 (ASCII or binary), regions as physical tags; atomically (temp + rename).
void write_msh(const std::filesystem::path& path, const mesh::Mesh& mesh, MshVersion version = MshVersion::kV41,
               bool binary = false);

}  // namespace hooke::io
