#include <hooke/core/error.hpp>
#include <hooke/io/detail/extension.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/io/obj.hpp>
#include <hooke/io/off.hpp>
#include <hooke/io/stl.hpp>
#include <hooke/io/tetgen.hpp>
#include <hooke/io/vtu.hpp>
#include <mutex>
#include <optional>
#include <vector>

namespace hooke::io {
namespace {

using detail::lower_extension;

std::mutex& readers_mutex() {
  static std::mutex m;
  return m;
}
std::vector<MeshReader>& readers() {
  static std::vector<MeshReader> r;
  return r;
}

[[noreturn]] void unknown(const std::filesystem::path& path) {
  std::string more;
  {
    const std::lock_guard lock(readers_mutex());
    for (const MeshReader& r : readers()) more += ", " + r.extensions;
  }
  throw InvalidArgument("cannot tell the format of '" + path.string() +
                        "' from its extension (use .msh, .vtu, .node/.ele/.face, .obj, .off, .stl" + more + ")");
}

}  // namespace

void register_mesh_reader(MeshReader reader) {
  const std::lock_guard lock(readers_mutex());
  for (const MeshReader& r : readers())
    if (r.extensions == reader.extensions) return;
  readers().push_back(std::move(reader));
}

mesh::Mesh read_mesh(const std::filesystem::path& path, const ReadOptions& options) {
  const std::string ext = lower_extension(path);
  mesh::Mesh m;
  std::optional<MeshReader> registered;  // a copy: another thread may register meanwhile
  {
    const std::lock_guard lock(readers_mutex());
    for (const MeshReader& r : readers())
      if (r.accepts(path)) registered = r;
  }
  if (registered) {
    m = registered->read(path);
    if (options.validate) mesh::validate(m, options.validation);
    return m;
  }
  if (ext == ".msh")
    m = read_msh(path);
  else if (ext == ".vtu")
    m = read_vtu(path).mesh;
  else if (ext == ".node" || ext == ".ele" || ext == ".face")
    m = read_tetgen(path);
  else if (ext == ".obj")
    m = read_obj(path);
  else if (ext == ".off")
    m = read_off(path);
  else if (ext == ".stl")
    m = read_stl(path);
  else
    unknown(path);
  if (!(options.metres_per_unit > 0.0)) throw InvalidArgument("the unit scale must be positive");
  m.nodes *= options.metres_per_unit;
  if (options.validate) mesh::validate(m, options.validation);
  return m;
}

void write_mesh(const std::filesystem::path& path, const mesh::Mesh& mesh, const WriteOptions& options) {
  const std::string ext = lower_extension(path);
  if (ext == ".msh")
    write_msh(path, mesh, options.msh_version, options.binary);
  else if (ext == ".vtu")
    write_vtu(path, mesh);
  else if (ext == ".node" || ext == ".ele" || ext == ".face")
    write_tetgen(path, mesh);
  else if (ext == ".obj")
    write_obj(path, mesh);
  else if (ext == ".off")
    write_off(path, mesh);
  else if (ext == ".stl")
    write_stl(path, mesh, options.binary);
  else
    unknown(path);
}

}  // namespace hooke::io
