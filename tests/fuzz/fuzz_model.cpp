// libFuzzer target: the model-file reader (calibrate::parse_model, what `--model MODEL.json` reads) on arbitrary
// bytes. Any hooke::Error is a correct answer; a crash, a sanitizer report, a hang or an allocation beyond
// -malloc_limit_mb is a bug.
#include <cstdint>
#include <hooke/calibrate/model_file.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/log.hpp>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool quiet = (hooke::set_log_sink({}), true);
  (void)quiet;
  try {
    hooke::calibrate::parse_model(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
  } catch (const hooke::Error&) {
  }
  return 0;
}
