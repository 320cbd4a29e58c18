#include <fstream>
#include <hooke/core/atomic_file.hpp>
#include <hooke/core/error.hpp>
#include <hooke/io/pvd.hpp>
#include <iomanip>
#include <regex>

namespace hooke::io {

void write_pvd(const std::filesystem::path& path, const std::vector<PvdFrame>& frames) {
  write_file_atomically(path, [&](std::ostream& o) {
    o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <Collection>\n"
      << std::setprecision(17);
    for (const auto& f : frames)
      o << "    <DataSet timestep=\"" << f.time << "\" group=\"\" part=\"0\" file=\"" << f.file << "\"/>\n";
    o << "  </Collection>\n</VTKFile>\n";
  });
}

std::vector<PvdFrame> read_pvd(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw IoError("cannot open " + path.string());
  const std::regex time_re("timestep=\"([^\"]*)\""), file_re("file=\"([^\"]*)\"");
  std::vector<PvdFrame> frames;
  std::string line;
  for (std::int64_t n = 1; std::getline(in, line); ++n) {
    if (line.find("<DataSet") == std::string::npos) continue;
    std::smatch t, f;
    if (!std::regex_search(line, t, time_re) || !std::regex_search(line, f, file_re))
      throw ParseError(path.string(), n, "DataSet without timestep and file attributes");
    try {
      frames.push_back({std::stod(t[1].str()), f[1].str()});
    } catch (const std::exception&) {
      throw ParseError(path.string(), n, "timestep '" + t[1].str() + "' is not a number");
    }
  }
  return frames;
}

}  // namespace hooke::io
