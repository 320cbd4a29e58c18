#include <hooke/core/error.hpp>
#include <hooke/io/series.hpp>
#include <hooke/io/vtu.hpp>

namespace hooke::io {

namespace fs = std::filesystem;

SeriesWriter::SeriesWriter(fs::path dir, mesh::Mesh mesh)
    : m_dir(std::move(dir)), m_partial(m_dir / "frames.partial"), m_mesh(std::move(mesh)) {
  std::error_code ec;
  fs::create_directories(m_dir, ec);
  if (ec || !fs::is_directory(m_dir))
    throw IoError("cannot create the output folder '" + m_dir.string() + "'" + (ec ? ": " + ec.message() : ""));
  fs::remove_all(m_partial, ec);
  fs::create_directories(m_partial, ec);
  if (ec) throw IoError("cannot create '" + m_partial.string() + "': " + ec.message());
}

SeriesWriter::~SeriesWriter() {
  std::error_code ec;
  if (!m_committed) fs::remove_all(m_partial, ec);
}

void SeriesWriter::write(double time, const std::vector<Field>& point_data) {
  const std::string name = "frame_" + std::to_string(m_frames.size()) + ".vtu";
  write_vtu(m_partial / name, m_mesh, point_data);
  m_frames.push_back({time, "frames/" + name});
}

fs::path SeriesWriter::commit() {
  const fs::path pvd = m_dir / "simulation.pvd", frames = m_dir / "frames";
  std::error_code ec;
  fs::remove(pvd, ec);  // first: a .pvd never outlives its frames
  fs::remove_all(frames, ec);
  fs::rename(m_partial, frames, ec);
  if (ec) throw IoError("cannot rename '" + m_partial.string() + "' to '" + frames.string() + "': " + ec.message());
  m_committed = true;
  write_pvd(pvd, m_frames);
  return pvd;
}

}  // namespace hooke::io
