#pragma once
/// Wavefront OBJ: vertices and polygon faces (triangles; quads on planar meshes).
#include <filesystem>
#include <hooke/mesh/mesh.hpp>

namespace hooke::io {

/// Reads "v x y z" and "f a b c [d]" records (a may be a, a/t, a//n, a/t/n; negative = relative); other
/// records (vt, vn, o, g, usemtl, s, ...) are ignored. A mesh with all z = 0 becomes planar; quads are
/// allowed only there. @throws IoError, ParseError{file, line}
mesh::Mesh read_obj(const std::filesystem::path& path);

/// Writes vertices and faces (1-based), atomically.
void write_obj(const std::filesystem::path& path, const mesh::Mesh& mesh);

}  // namespace hooke::io
