#pragma once
/// TetGen .node / .ele / .face files.
#include <filesystem>
#include <hooke/mesh/mesh.hpp>

namespace hooke::io {

/// Reads a TetGen mesh. `path` names any of base.node, base.ele, base.face: with .face, the surface
/// triangles of base.face are read (a surface mesh); otherwise base.node + base.ele (tets, first attribute
/// = region). Indices may start at 0 or 1 (taken from the first point of the .node file). Tets given with
/// TetGen's negative orientation throughout are reordered to positive volume.
/// @throws IoError, ParseError{file, line}
mesh::Mesh read_tetgen(const std::filesystem::path& path);

/// Writes base.node and, for tets, base.ele plus base.face (boundary faces, outward); for surface meshes
/// base.face. 1-based indices; regions as the .ele attribute. `path` may carry any of the three extensions.
void write_tetgen(const std::filesystem::path& path, const mesh::Mesh& mesh);

}  // namespace hooke::io
