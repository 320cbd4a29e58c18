#pragma once
// Consistent nodal loads of a uniform traction on the top face (z = height) of a triangle surface.
#include <hooke/mesh/mesh.hpp>

namespace hooke::experiments::detail {

// Flat nodal forces (N, 3 per node): traction (Pa) x A_t / 3 at each node of every triangle lying in z = height.
inline VecX top_face_load(const mesh::Mesh& surface, double height, const Vec3& traction) {
  VecX f = VecX::Zero(3 * surface.node_count());
  for (int t = 0; t < surface.element_count(); ++t) {
    bool top = true;
    for (int k = 0; k < 3; ++k) top = top && surface.nodes(surface.elements(t, k), 2) > height * (1.0 - 1e-12);
    if (!top) continue;
    const Vec3 p0 = surface.nodes.row(surface.elements(t, 0)).transpose(),
               p1 = surface.nodes.row(surface.elements(t, 1)).transpose(),
               p2 = surface.nodes.row(surface.elements(t, 2)).transpose();
    const double area = 0.5 * (p1 - p0).cross(p2 - p0).norm();
    for (int k = 0; k < 3; ++k) f.segment<3>(3 * surface.elements(t, k)) += traction * (area / 3.0);
  }
  return f;
}

}  // namespace hooke::experiments::detail
