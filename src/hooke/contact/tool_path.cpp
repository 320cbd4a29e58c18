#include <algorithm>
#include <cmath>
#include <hooke/contact/tool_path.hpp>
#include <hooke/core/error.hpp>
#include <hooke/io/csv.hpp>
#include <string>

namespace hooke::contact {

ToolPath::ToolPath(std::vector<TimedPose> poses) : m_poses(std::move(poses)) {
  if (m_poses.empty()) throw InvalidArgument("a tool path needs at least one pose");
  for (std::size_t k = 0; k < m_poses.size(); ++k)
    if (!std::isfinite(m_poses[k].time) || (k > 0 && !(m_poses[k].time > m_poses[k - 1].time)))
      throw InvalidArgument("tool path: pose " + std::to_string(k + 1) + " at t = " + std::to_string(m_poses[k].time) +
                            " s is not after the one before it");
}

Pose ToolPath::at(double time) const {
  if (time <= m_poses.front().time) return m_poses.front().pose;
  if (time >= m_poses.back().time) return m_poses.back().pose;
  const auto next =
      std::upper_bound(m_poses.begin(), m_poses.end(), time, [](double t, const TimedPose& p) { return t < p.time; });
  const TimedPose& b = *next;
  const TimedPose& a = *(next - 1);
  const double s = (time - a.time) / (b.time - a.time);
  Pose p;
  p.position = (1.0 - s) * a.pose.position + s * b.pose.position;
  const Eigen::Quaterniond qa(a.pose.rotation), qb(b.pose.rotation);
  p.rotation = qa.slerp(s, qb).normalized().toRotationMatrix();
  return p;
}

ToolPath read_tool_path(const std::filesystem::path& path, double metres_per_unit) {
  const io::CsvTable t = io::read_csv_table(path);
  const auto column = [&](const char* name) {
    const int c = t.column(name);
    if (c < 0)
      throw InvalidArgument(path.string() + ": no column '" + name +
                            "' (a tool path has columns t, x, y, z and optionally qw, qx, qy, qz)");
    return c;
  };
  const int ct = column("t"), cx = column("x"), cy = column("y"), cz = column("z");
  const bool oriented = t.column("qw") >= 0;
  std::vector<TimedPose> poses;
  for (Eigen::Index r = 0; r < t.values.rows(); ++r) {
    TimedPose p;
    p.time = t.values(r, ct);
    p.pose.position = metres_per_unit * Vec3(t.values(r, cx), t.values(r, cy), t.values(r, cz));
    if (oriented) {
      const Eigen::Quaterniond q(t.values(r, column("qw")), t.values(r, column("qx")), t.values(r, column("qy")),
                                 t.values(r, column("qz")));
      if (!(std::abs(q.norm() - 1.0) < 1e-6))
        throw InvalidArgument(path.string() + ": row " + std::to_string(r + 1) +
                              ": the orientation (qw, qx, qy, qz) is not a unit quaternion");
      p.pose.rotation = q.toRotationMatrix();
    }
    poses.push_back(p);
  }
  try {
    return ToolPath(std::move(poses));
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(path.string() + ": " + e.what());
  }
}

}  // namespace hooke::contact
