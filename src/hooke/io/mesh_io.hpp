#pragma once
/// Reading and writing meshes by file extension, with unit conversion and validation.
#include <filesystem>
#include <functional>
#include <hooke/io/msh.hpp>
#include <hooke/mesh/mesh.hpp>
#include <hooke/mesh/validate.hpp>
#include <string>

namespace hooke::io {

struct ReadOptions {
  double metres_per_unit = 1.0;        ///< coordinate scale: 0.01 for a file in cm (see metres_per_unit()), default 1
  bool validate = true;                ///< run mesh::validate (and reorient), default true
  mesh::ValidationOptions validation;  ///< passed to mesh::validate
};

/// Reads .msh, .vtu, .node/.ele/.face (TetGen), .obj, .off or .stl, scales the coordinates to metres and
/// validates; or a file of a registered reader (register_mesh_reader: label images, already in metres, so that the
/// scale does not apply), validated. @throws IoError, ParseError, InvalidMesh, InvalidArgument (unknown extension)
mesh::Mesh read_mesh(const std::filesystem::path& path, const ReadOptions& options = {});

/// A reader of files this layer does not parse itself (label images: hooke::image, through ITK), returning a
/// mesh in metres; read_mesh validates it.
struct MeshReader {
  std::function<bool(const std::filesystem::path&)> accepts;  ///< true for the files it reads (by extension)
  std::function<mesh::Mesh(const std::filesystem::path&)> read;
  std::string extensions;  ///< as error messages list them (".nii, .nii.gz, ...")
};
/// Adds `reader` to those read_mesh tries first (once per `reader.extensions`; later calls with the same
/// extensions are ignored). Thread-safe.
void register_mesh_reader(MeshReader reader);

struct WriteOptions {
  MshVersion msh_version = MshVersion::kV41;  ///< for .msh, default 4.1
  bool binary = false;                        ///< for .msh and .stl, default ASCII
};

/// Writes `mesh` in the format named by the extension (.msh, .vtu, .node/.ele, .obj, .off, .stl), atomically.
void write_mesh(const std::filesystem::path& path, const mesh::Mesh& mesh, const WriteOptions& options = {});

}  // namespace hooke::io
