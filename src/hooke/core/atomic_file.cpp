#include <hooke/core/atomic_file.hpp>

#include <fstream>
#include <hooke/core/error.hpp>
#include <random>
#include <string>

namespace hooke {

void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
                           bool binary) {
  namespace fs = std::filesystem;
  std::random_device entropy;
  const fs::path tmp = path.string() + ".tmp" + std::to_string(entropy() % 1000000);
  try {
    {
      std::ofstream out(tmp, binary ? std::ios::out | std::ios::binary : std::ios::out);
      if (!out) throw IoError("cannot create '" + tmp.string() + "' (does the folder exist and is it writable?)");
      write(out);
      out.flush();
      if (!out) throw IoError("failed while writing '" + path.string() + "'");
    }
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) throw IoError("cannot rename '" + tmp.string() + "' to '" + path.string() + "': " + ec.message());
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
}

void create_output_folder(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw IoError("the output folder '" + dir.string() + "' is a file; give a folder");
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw IoError("cannot create the output folder '" + dir.string() + "'" + (ec ? ": " + ec.message() : ""));
  // Writable: a probe file (permission bits alone do not show read-only mounts).
  std::random_device entropy;
  const fs::path probe = dir / (".hooke-write-test" + std::to_string(entropy() % 1000000));
  {
    std::ofstream out(probe);
    if (!out) throw IoError("cannot write into the output folder '" + dir.string() + "' (is it read-only?)");
  }
  fs::remove(probe, ec);
}

}  // namespace hooke
