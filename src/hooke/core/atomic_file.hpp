#pragma once
/// Output files are never half-written: content goes to a temporary file beside the target,
/// which is renamed over it only when complete.
#include <filesystem>
#include <functional>
#include <ostream>

namespace hooke {

/// Writes `path` through `write` into a temporary sibling file, then renames it into place.
/// If `write` throws or the stream fails, the temporary is removed and `path` is untouched.
/// @param binary  open the stream in binary mode
/// @throws IoError when the file cannot be created, written or renamed
void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
                           bool binary = false);

/// Makes `dir` (and its parents) an existing, writable folder for a command's outputs.
/// @throws IoError naming `dir` when it is a file, cannot be created, or cannot be written into
void create_output_folder(const std::filesystem::path& dir);

}  // namespace hooke
