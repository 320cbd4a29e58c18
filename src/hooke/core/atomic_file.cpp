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

}  // namespace hooke
