#include <algorithm>
#include <cmath>
#include <hooke/surface/normal_cone.hpp>

namespace hooke::surface {

Mat3 unpack_cone(const ConeRow& r) {
  Mat3 p;
  p << r(0), r(3), r(4), r(3), r(1), r(5), r(4), r(5), r(2);
  return p;
}

ConeRow pack_cone(const Mat3& p) {
  ConeRow r;
  r << p(0, 0), p(1, 1), p(2, 2), 0.5 * (p(0, 1) + p(1, 0)), 0.5 * (p(0, 2) + p(2, 0)), 0.5 * (p(1, 2) + p(2, 1));
  return r;
}

ConeRow smooth_cone(const Vec3& normal) { return pack_cone(normal * normal.transpose()); }

namespace {

// Smoothstep of the tangential moment t between a smooth node (dihedral angle 25 deg) and a crease (60 deg).
double crease_weight(double t) {
  const double lo = std::pow(std::tan(12.5 * M_PI / 180.0), 2), hi = std::pow(std::tan(30.0 * M_PI / 180.0), 2);
  const double s = std::clamp((t - lo) / (hi - lo), 0.0, 1.0);
  return s * s * (3.0 - 2.0 * s);
}

}  // namespace

RowMatX node_normal_cones(const RowMatXi& triangles, const Eigen::Ref<const VecX>& x, const RowMatX& normals) {
  const Eigen::Index n = normals.rows();
  std::vector<Mat3> moment(static_cast<size_t>(n), Mat3::Zero());
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    const Vec3 a = x.segment<3>(3 * triangles(t, 0)), b = x.segment<3>(3 * triangles(t, 1)),
               c = x.segment<3>(3 * triangles(t, 2));
    const Vec3 area2 = (b - a).cross(c - a);  // twice the area times the unit normal
    const double l = area2.norm();
    if (l == 0.0) continue;
    const Mat3 m = area2 * area2.transpose() / l;  // 2 A_t N_t N_t^T
    for (int k = 0; k < 3; ++k) moment[static_cast<size_t>(triangles(t, k))] += m;
  }
  RowMatX cones(n, 6);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Vec3 normal = normals.row(i).transpose();
    const Mat3& m = moment[static_cast<size_t>(i)];
    const Mat3 tangent = Mat3::Identity() - normal * normal.transpose();
    Mat3 p = normal * normal.transpose();
    const double along = normal.dot(m * normal);
    if (along > 0.0) {
      const Eigen::SelfAdjointEigenSolver<Mat3> eig(tangent * m * tangent / along);
      for (int k = 0; k < 3; ++k) {
        const double w = crease_weight(eig.eigenvalues()(k));
        if (w > 0.0) p += w * eig.eigenvectors().col(k) * eig.eigenvectors().col(k).transpose();
      }
    }
    cones.row(i) = pack_cone(p);
  }
  return cones;
}

}  // namespace hooke::surface
