#pragma once
/// Object File Format (OFF): vertex and face lists.
#include <filesystem>
#include <hooke/mesh/mesh.hpp>

namespace hooke::io {

/// Reads an ASCII OFF file ("OFF" header, counts, vertices, faces "n i j k ..." with optional colours).
/// Triangles, and quads on planar meshes. @throws IoError, ParseError{file, line}
mesh::Mesh read_off(const std::filesystem::path& path);

/// Writes an ASCII OFF file, atomically.
void write_off(const std::filesystem::path& path, const mesh::Mesh& mesh);

}  // namespace hooke::io
