// libFuzzer target: hooke's label-image reader (HOOKE_FUZZ_FORMAT: nii, nii.gz, nrrd or mha) on arbitrary bytes,
// through image::read_label_image as a user's file would go: hooke's checks before ITK reads (the byte counts, the
// size bound) and ITK's reading behind them. Any hooke::Error is a correct answer; a crash, a sanitizer report, a
// hang or an allocation beyond -malloc_limit_mb is a bug. ITK's own libraries are Debian's, not instrumented: the
// coverage that guides the fuzzer is hooke's and the ITK templates the bridge instantiates.
#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <hooke/core/error.hpp>
#include <hooke/image/label_image.hpp>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = "/dev/shm/hooke_fuzz_" + std::to_string(getpid()) + "." HOOKE_FUZZ_FORMAT;
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  try {
    hooke::image::read_label_image(path);
  } catch (const hooke::Error&) {
  }
  return 0;
}
