#pragma once
/// Where a tool is over time: a table of timed poses, interpolated (positions linearly, orientations along the
/// shortest rotation), read from a CSV file `t,x,y,z[,qw,qx,qy,qz]` (s, m, a unit quaternion). docs/contact.md.
#include <filesystem>
#include <hooke/contact/rigid_tool.hpp>
#include <vector>

namespace hooke::contact {

struct TimedPose {
  double time = 0.0;  ///< s
  Pose pose;
};

class ToolPath {
 public:
  ToolPath() = default;
  /// @param poses  at least one, times strictly increasing and finite
  /// @throws InvalidArgument naming the first pose out of order
  explicit ToolPath(std::vector<TimedPose> poses);
  bool empty() const { return m_poses.empty(); }
  /// The pose at time t (s): held at the first pose before it and at the last after it. @pre !empty()
  Pose at(double time) const;
  const std::vector<TimedPose>& poses() const { return m_poses; }

 private:
  std::vector<TimedPose> m_poses;
};

/// Reads a path table: a header with columns t, x, y, z (and optionally qw, qx, qy, qz), one pose per row; positions
/// in the mesh's unit times `metres_per_unit`.
/// @throws IoError, ParseError (io::read_csv_table: file and line); InvalidArgument naming the file for a missing
///         column, a quaternion that is not of unit length, or times out of order
ToolPath read_tool_path(const std::filesystem::path& path, double metres_per_unit = 1.0);

}  // namespace hooke::contact
