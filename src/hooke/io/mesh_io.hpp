#pragma once
/// Reading and writing meshes by file extension, with unit conversion and validation.
#include <filesystem>
#include <hooke/io/msh.hpp>
#include <hooke/mesh/mesh.hpp>
#include <hooke/mesh/validate.hpp>

namespace hooke::io {

struct ReadOptions {
  double metres_per_unit = 1.0;        ///< coordinate scale: 0.01 for a file in cm (see metres_per_unit()), default 1
  bool validate = true;                ///< run mesh::validate (and reorient), default true
  mesh::ValidationOptions validation;  ///< passed to mesh::validate
};

/// Reads .msh, .vtu, .node/.ele/.face (TetGen), .obj, .off or .stl; scales the coordinates to metres
/// and validates. @throws IoError, ParseError, InvalidMesh, InvalidArgument (unknown extension)
mesh::Mesh read_mesh(const std::filesystem::path& path, const ReadOptions& options = {});

struct WriteOptions {
  MshVersion msh_version = MshVersion::kV41;  ///< for .msh, default 4.1
  bool binary = false;                        ///< for .msh and .stl, default ASCII
};

/// Writes `mesh` in the format named by the extension (.msh, .vtu, .node/.ele, .obj, .off, .stl), atomically.
void write_mesh(const std::filesystem::path& path, const mesh::Mesh& mesh, const WriteOptions& options = {});

}  // namespace hooke::io
