#pragma once
// A file `name` in the folder `folder` under the system's temporary directory (created), for tests that write files.
#include <filesystem>
#include <string>

namespace hooke::test {

inline std::filesystem::path scratch_file(const std::string& folder, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / folder;
  std::filesystem::create_directories(dir);
  return dir / name;
}

}  // namespace hooke::test
