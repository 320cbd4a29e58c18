#include <cmath>
#include <hooke/contact/tool_surface.hpp>
#include <hooke/core/error.hpp>
#include <numbers>
#include <string>
#include <vector>

namespace hooke::contact {

ToolSurface tool_surface(const RigidTool& tool, int segments, double extent) {
  if (segments < 8)
    throw InvalidArgument("a tool's surface needs at least 8 segments, not " + std::to_string(segments));
  const Pose& pose = tool.pose();
  ToolSurface s;
  if (tool.shape() == ToolShape::kMesh) {  // its own triangles, moved
    const mesh::Mesh& m = tool.triangles()->surface();
    s.nodes = ((m.nodes * pose.rotation.transpose()).rowwise() + pose.position.transpose()).eval();
    s.triangles = m.elements;
    return s;
  }
  if (tool.shape() == ToolShape::kHalfSpace) {
    if (!(extent > 0.0)) throw InvalidArgument("a plane's drawn square needs an extent > 0 m");
    s.nodes.resize(4, 3);
    const double corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int k = 0; k < 4; ++k)
      s.nodes.row(k) =
          (pose.rotation * Vec3(extent * corners[k][0], extent * corners[k][1], 0.0) + pose.position).transpose();
    s.triangles.resize(2, 3);
    s.triangles << 0, 1, 2, 0, 2, 3;
    return s;
  }
  // Rings of latitude from the south pole to the north, each hemisphere's centre shifted by -L/2 and +L/2 along the
  // local z: a capsule's cylinder is the band between the two equators (one equator for a sphere).
  const int around = (segments + 3) / 4 * 4, half = around / 4;  // rings per hemisphere, the equator included
  const double r = tool.radius(), l = tool.length();
  struct Ring {
    double latitude, shift;
  };
  std::vector<Ring> rings;
  for (int k = 1; k <= half; ++k) rings.push_back({-std::numbers::pi / 2 + k * std::numbers::pi / (2 * half), -l / 2});
  for (int k = l > 0.0 ? 0 : 1; k < half; ++k) rings.push_back({k * std::numbers::pi / (2 * half), l / 2});
  const int n_rings = static_cast<int>(rings.size());
  s.nodes.resize(2 + n_rings * around, 3);
  auto put = [&](int row, const Vec3& local) {
    s.nodes.row(row) = (pose.rotation * local + pose.position).transpose();
  };
  put(0, Vec3(0.0, 0.0, -r - l / 2));
  put(1, Vec3(0.0, 0.0, r + l / 2));
  for (int i = 0; i < n_rings; ++i)
    for (int j = 0; j < around; ++j) {
      const double a = 2.0 * std::numbers::pi * j / around, c = std::cos(rings[i].latitude);
      put(2 + i * around + j,
          Vec3(r * c * std::cos(a), r * c * std::sin(a), r * std::sin(rings[i].latitude) + rings[i].shift));
    }
  auto node = [&](int ring, int j) { return 2 + ring * around + (j % around); };
  std::vector<std::array<int, 3>> t;
  for (int j = 0; j < around; ++j) {
    t.push_back({0, node(0, j + 1), node(0, j)});
    t.push_back({1, node(n_rings - 1, j), node(n_rings - 1, j + 1)});
    for (int i = 0; i + 1 < n_rings; ++i) {
      t.push_back({node(i, j), node(i, j + 1), node(i + 1, j + 1)});
      t.push_back({node(i, j), node(i + 1, j + 1), node(i + 1, j)});
    }
  }
  s.triangles.resize(static_cast<Eigen::Index>(t.size()), 3);
  for (std::size_t f = 0; f < t.size(); ++f)
    for (int k = 0; k < 3; ++k) s.triangles(static_cast<Eigen::Index>(f), k) = t[f][static_cast<std::size_t>(k)];
  return s;
}

}  // namespace hooke::contact
