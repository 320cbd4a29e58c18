// ParaView collections: written frames read back; a DataSet without its attributes is named by line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <hooke/core/error.hpp>
#include <hooke/io/pvd.hpp>

namespace hooke::io {
namespace {

TEST(Pvd, FramesRoundTrip) {
  const auto path = std::filesystem::temp_directory_path() / "hooke_test_series.pvd";
  const std::vector<PvdFrame> frames{{0.0, "frames/frame_0.vtu"}, {1e-3 / 3.0, "frames/frame_1.vtu"}};
  write_pvd(path, frames);
  const auto back = read_pvd(path);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].time, frames[1].time);  // 17 significant digits: exact
  EXPECT_EQ(back[1].file, frames[1].file);
  std::filesystem::remove(path);
}

TEST(Pvd, DataSetWithoutFileIsNamedByLine) {
  const auto path = std::filesystem::temp_directory_path() / "hooke_test_bad.pvd";
  std::ofstream(path) << "<VTKFile type=\"Collection\">\n<Collection>\n<DataSet timestep=\"0\"/>\n</Collection>\n";
  try {
    read_pvd(path);
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 3);
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace hooke::io
