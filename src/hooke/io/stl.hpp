#pragma once
/// STL triangle soups, ASCII and binary.
#include <filesystem>
#include <hooke/mesh/mesh.hpp>

namespace hooke::io {

/// Reads an ASCII or binary STL file (binary when the size is 84 + 50 n bytes for the count n in its
/// header). Coincident vertices (bit-identical coordinates) are merged. Facet normals are ignored.
/// @throws IoError, ParseError{file, line} (ASCII) or ParseError{file, byte} (binary)
mesh::Mesh read_stl(const std::filesystem::path& path);

/// Writes a triangle mesh as STL (binary: float32 coordinates; ASCII: full precision), atomically.
void write_stl(const std::filesystem::path& path, const mesh::Mesh& mesh, bool binary = true);

}  // namespace hooke::io
