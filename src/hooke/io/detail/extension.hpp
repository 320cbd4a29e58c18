#pragma once
// File extensions compared without regard to case (".FACE" is a TetGen face file like ".face").
#include <cctype>
#include <filesystem>
#include <string>

namespace hooke::io::detail {

// The extension of `path` with its dot, in lower case ("" when it has none).
inline std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace hooke::io::detail
