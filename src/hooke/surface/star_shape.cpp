#include <hooke/core/error.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/surface/discretisation.hpp>
#include <hooke/surface/star_shape.hpp>
#include <sstream>

namespace hooke::surface {
namespace {

std::string where(const mesh::Mesh& m) { return m.source.empty() ? std::string() : " of " + m.source; }

std::string point(const Vec3& p) {
  std::ostringstream s;
  s.precision(6);
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

}  // namespace

void require_star_shaped(const mesh::Mesh& m, const Vec3& centre) {
  const double size = mesh::bounding_box_diagonal(m);
  for (int t = 0; t < m.element_count(); ++t) {
    const Vec3 a = m.nodes.row(m.elements(t, 0)).transpose(), b = m.nodes.row(m.elements(t, 1)).transpose(),
               c = m.nodes.row(m.elements(t, 2)).transpose();
    if (!(mesh::signed_volume(centre, a, b, c) > 1e-14 * size * size * size))
      throw InvalidMesh(mesh::element_label(m, t) + " does not face away from the centre " + point(centre) +
                            ": the surface is not star-shaped from it, so radial links would cross the surface "
                            "(give another centre, or use a volume mesh)",
                        t);
  }
  const VecX x = Eigen::Map<const VecX>(m.nodes.data(), m.nodes.size());
  const RowMatX normals = node_normals(m.elements, x);
  for (int i = 0; i < m.node_count(); ++i)
    if (!((m.nodes.row(i) - centre.transpose()).dot(normals.row(i)) > 1e-9 * size))
      throw InvalidMesh("node " + std::to_string(i) + where(m) + " has the centre " + point(centre) +
                        " in front of its tangent plane: its inner spring axis (Fig. 6) would point out of the body");
}

}  // namespace hooke::surface
