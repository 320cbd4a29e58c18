// A tool's path: positions interpolated linearly and orientations along the shortest rotation between timed poses,
// held before the first and after the last, read from a CSV table that is refused when malformed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <hooke/contact/tool_path.hpp>
#include <hooke/core/error.hpp>

namespace hooke::contact {
namespace {

TEST(ToolPath, InterpolatesPositionsAndRotationsAndHoldsTheEnds) {
  const Mat3 quarter = Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()).toRotationMatrix();
  const ToolPath path({{0.0, {Vec3(0.0, 0.0, 1.0), Mat3::Identity()}}, {2.0, {Vec3(2.0, 0.0, 0.0), quarter}}});
  const Pose mid = path.at(1.0);
  EXPECT_LT((mid.position - Vec3(1.0, 0.0, 0.5)).norm(), 1e-15);
  EXPECT_LT((mid.rotation - Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ()).toRotationMatrix()).norm(), 1e-12);
  EXPECT_EQ(path.at(-1.0).position, Vec3(0.0, 0.0, 1.0));
  EXPECT_EQ(path.at(5.0).position, Vec3(2.0, 0.0, 0.0));
}

TEST(ToolPath, ReadsATableAndRefusesBadOnes) {
  const auto dir = std::filesystem::temp_directory_path() / "hooke_tool_path";
  std::filesystem::create_directories(dir);
  const auto write = [&](const char* name, const char* text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  };
  const ToolPath path =
      read_tool_path(write("ok.csv", "t,x,y,z,qw,qx,qy,qz\n0,0,0,10,1,0,0,0\n1,0,0,5,0,0,0,1\n"), 1e-3);
  ASSERT_EQ(path.poses().size(), 2u);
  EXPECT_NEAR(path.at(0.5).position.z(), 0.0075, 1e-15);
  EXPECT_LT((path.poses()[1].pose.rotation - Eigen::AngleAxisd(M_PI, Vec3::UnitZ()).toRotationMatrix()).norm(), 1e-12);
  for (const auto& [name, text, what] :
       {std::tuple{"no_t.csv", "time,x,y,z\n0,0,0,0\n", "no column 't'"},
        std::tuple{"order.csv", "t,x,y,z\n1,0,0,0\n1,0,0,1\n", "not after"},
        std::tuple{"quaternion.csv", "t,x,y,z,qw,qx,qy,qz\n0,0,0,0,2,0,0,0\n", "unit quaternion"}}) {
    try {
      read_tool_path(write(name, text));
      ADD_FAILURE() << name << " was read";
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace hooke::contact
