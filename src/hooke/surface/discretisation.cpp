#include <hooke/core/error.hpp>
#include <hooke/mesh/closed_surface.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/surface/discretisation.hpp>

namespace hooke::surface {

RowMatX node_normals(const RowMatXi& triangles, const Eigen::Ref<const VecX>& x) {
  RowMatX n = RowMatX::Zero(x.size() / 3, 3);
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    const Vec3 a = x.segment<3>(3 * triangles(t, 0)), b = x.segment<3>(3 * triangles(t, 1)),
               c = x.segment<3>(3 * triangles(t, 2));
    const Vec3 area2 = (b - a).cross(c - a);  // twice the area times the unit normal
    for (int k = 0; k < 3; ++k) n.row(triangles(t, k)) += area2.transpose();
  }
  n.rowwise().normalize();
  return n;
}

Discretisation discretise(const mesh::Mesh& m, const Vec3& centre) {
  Discretisation d;
  d.centre = centre;
  const VecX x = Eigen::Map<const VecX>(m.nodes.data(), m.nodes.size());
  d.volume = mesh::enclosed_volume(m.elements, x);
  d.normals = node_normals(m.elements, x);
  const int n = m.node_count();
  d.radial_length.resize(n);
  d.normal_length.resize(n);
  for (int i = 0; i < n; ++i) {
    const Vec3 r = m.nodes.row(i).transpose() - centre;
    d.radial_length(i) = r.norm();
    d.normal_length(i) = r.dot(d.normals.row(i).transpose());
  }
  d.radial_volume = VecX::Zero(n);
  d.normal_volume = VecX::Zero(n);
  for (int t = 0; t < m.element_count(); ++t) {
    const Vec3 a = m.nodes.row(m.elements(t, 0)).transpose(), b = m.nodes.row(m.elements(t, 1)).transpose(),
               c = m.nodes.row(m.elements(t, 2)).transpose();
    const double cone = mesh::signed_volume(centre, a, b, c);
    for (int k = 0; k < 3; ++k) {
      const int i = m.elements(t, k);
      d.radial_volume(i) += cone;
      // Fig. 6: the same triangle seen from c_i, the foot of the node's normal line nearest to c. |.|: with a
      // strongly curved neighbourhood c_i may lie in front of a far triangle's plane; its volume still counts.
      const Vec3 ci = m.nodes.row(i).transpose() - d.normal_length(i) * d.normals.row(i).transpose();
      d.normal_volume(i) += std::abs(mesh::signed_volume(ci, a, b, c));
    }
  }
  return d;
}

VecX estimated_masses(const Discretisation& d, double total_mass) {
  if (!(total_mass > 0.0)) throw InvalidArgument("the object mass must be positive (kg)");
  return d.radial_volume * (total_mass / d.radial_volume.sum());
}

}  // namespace hooke::surface
