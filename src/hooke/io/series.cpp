#include <hooke/core/atomic_file.hpp>
#include <hooke/core/error.hpp>
#include <hooke/io/series.hpp>
#include <hooke/io/vtu.hpp>
#include <random>

namespace hooke::io {

namespace fs = std::filesystem;

namespace {

// "frames-" and 8 random hex digits: a folder name no earlier run in this folder is likely to hold.
std::string unique_frames_name(const fs::path& dir) {
  std::random_device entropy;
  for (;;) {
    char name[32];
    std::snprintf(name, sizeof name, "frames-%08x", static_cast<unsigned>(entropy()));
    std::error_code ec;
    if (!fs::exists(dir / name, ec) && !fs::exists(dir / (std::string(name) + ".partial"), ec)) return name;
  }
}

}  // namespace

SeriesWriter::SeriesWriter(fs::path dir, mesh::Mesh mesh) : m_dir(std::move(dir)), m_mesh(std::move(mesh)) {
  std::error_code exists_ec;
  m_created_dir = !fs::exists(m_dir, exists_ec);
  create_output_folder(m_dir);
  m_name = unique_frames_name(m_dir);
  m_partial = m_dir / (m_name + ".partial");
  std::error_code ec;
  fs::create_directories(m_partial, ec);
  if (ec) throw IoError("cannot create '" + m_partial.string() + "': " + ec.message());
}

SeriesWriter::~SeriesWriter() {
  std::error_code ec;
  if (m_committed) return;
  fs::remove_all(m_partial, ec);
  fs::remove_all(m_dir / m_name, ec);        // renamed, but the .pvd was not written
  if (m_created_dir) fs::remove(m_dir, ec);  // a folder this run made, when empty: no trace of a failed run
}

void SeriesWriter::write(double time, const std::vector<Field>& point_data) {
  const std::string name = "frame_" + std::to_string(m_frames.size()) + ".vtu";
  write_vtu(m_partial / name, m_mesh, point_data);
  m_frames.push_back({time, m_name + "/" + name});
}

fs::path SeriesWriter::commit() {
  const fs::path pvd = m_dir / "simulation.pvd", frames = m_dir / m_name;
  std::error_code ec;
  fs::rename(m_partial, frames, ec);
  if (ec) throw IoError("cannot rename '" + m_partial.string() + "' to '" + frames.string() + "': " + ec.message());
  write_pvd(pvd, m_frames);  // atomic: the commit point
  m_committed = true;
  // Frames that no .pvd names any more; failures to remove them leave only unreferenced files behind.
  for (const fs::directory_entry& e : fs::directory_iterator(m_dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name != m_name && e.is_directory(ec) && (name == "frames" || name.rfind("frames-", 0) == 0))
      fs::remove_all(e.path(), ec);
  }
  return pvd;
}

}  // namespace hooke::io
