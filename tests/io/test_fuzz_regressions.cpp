// Every input in tests/fuzz/regressions/FORMAT/ (inputs that once crashed, hung or exhausted memory in a reader,
// issue 16) is read as the fuzz targets read it: through read_mesh with validation. A hooke::Error or a valid mesh
// is the only acceptable outcome; the issue-16 files (item*) and the fuzzer's findings so far (fuzz_*) are all
// malformed and must be rejected. Model files (model/) go through calibrate::read_model, label images (mha/, nii/,
// nii.gz/, nrrd/) through image::read_label_image. Under the
// sanitizer build this is where a regression would show as a report.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <hooke/calibrate/model_file.hpp>
#include <hooke/core/error.hpp>
#include <hooke/image/label_image.hpp>
#include <hooke/io/mesh_io.hpp>
#include <sstream>
#include <string>

namespace hooke::io {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The file read_mesh gets for `input` of `format` (TetGen inputs are split at "\n@\n" into .node and .ele).
fs::path as_mesh_file(const fs::path& input, const std::string& format) {
  const fs::path dir = fs::temp_directory_path() / "hooke_fuzz_regressions";
  fs::create_directories(dir);
  const std::string bytes = slurp(input);
  if (format != "tetgen") {
    const fs::path p = dir / ("input." + format);
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }
  const size_t split = bytes.find("\n@\n");
  std::ofstream(dir / "input.node", std::ios::binary) << bytes.substr(0, split);
  std::ofstream(dir / "input.ele", std::ios::binary)
      << (split == std::string::npos ? std::string() : bytes.substr(split + 3));
  return dir / "input.ele";
}

TEST(FuzzRegressions, EveryCommittedInputIsRejectedOrRead) {
  const fs::path root = HOOKE_FUZZ_REGRESSIONS;
  int inputs = 0;
  for (const auto& format_dir : fs::directory_iterator(root)) {
    const std::string format = format_dir.path().filename().string();
    for (const auto& entry : fs::directory_iterator(format_dir.path())) {
      ++inputs;
      const std::string name = entry.path().filename().string();
      bool rejected = false;
      try {
        if (format == "model") {
          const calibrate::CalibratedModel m = calibrate::read_model(entry.path());
          EXPECT_GT(m.mesh.node_count(), 0) << name;
        } else if (image::is_label_image_path("input." + format)) {  // as fuzz_image.cpp reads them
          EXPECT_GT(image::read_label_image(as_mesh_file(entry.path(), format)).voxel_count(), 0) << name;
        } else {
          const mesh::Mesh m = read_mesh(as_mesh_file(entry.path(), format));
          EXPECT_GT(m.element_count(), 0) << name;
        }
      } catch (const Error& e) {
        rejected = true;
        EXPECT_FALSE(std::string(e.what()).empty()) << name;
      }
      if (name.rfind("item", 0) == 0 || name.rfind("fuzz_", 0) == 0) {
        EXPECT_TRUE(rejected) << format << "/" << name << " was accepted";
      }
    }
  }
  EXPECT_GE(inputs, 11);
}

}  // namespace
}  // namespace hooke::io
