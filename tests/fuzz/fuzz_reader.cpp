// libFuzzer target: one of hooke's mesh readers (HOOKE_FUZZ_FORMAT) on arbitrary bytes, through read_mesh with
// validation, as a user's file would go. Any hooke::Error is a correct answer; a crash, a sanitizer report, a hang
// (libFuzzer -timeout) or an allocation beyond -malloc_limit_mb is a bug. TetGen inputs are split at the first
// "\n@\n" into the .node and the .ele file.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <hooke/core/error.hpp>
#include <hooke/core/log.hpp>
#include <hooke/io/mesh_io.hpp>
#include <string>
#include <string_view>

namespace {

std::string scratch(const char* ext) {
  return "/dev/shm/hooke_fuzz_" + std::to_string(getpid()) + ext;  // memory-backed: no disk traffic per input
}

void put(const std::string& path, std::string_view bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool quiet = (hooke::set_log_sink({}), true);  // validation warnings would flood the output
  (void)quiet;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const std::string format = HOOKE_FUZZ_FORMAT;
  std::string path;
  if (format == "tetgen") {
    const size_t split = bytes.find("\n@\n");
    put(scratch(".node"), bytes.substr(0, split));
    path = scratch(".ele");
    put(path, split == std::string_view::npos ? std::string_view() : bytes.substr(split + 3));
  } else {
    path = scratch(("." + format).c_str());
    put(path, bytes);
  }
  try {
    hooke::io::read_mesh(path);
  } catch (const hooke::Error&) {
  }
  return 0;
}
