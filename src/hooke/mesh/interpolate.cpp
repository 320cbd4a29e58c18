#include <hooke/core/error.hpp>
#include <hooke/mesh/interpolate.hpp>
#include <hooke/mesh/measure.hpp>
#include <string>

namespace hooke::mesh {
namespace {

// Barycentric coordinates of x in the simplex with corners `c` (rows), dim + 1 weights summing to one.
VecX barycentric(const MatX& c, const VecX& x) {
  const int d = static_cast<int>(c.cols());
  MatX a(d, d);
  for (int k = 0; k < d; ++k) a.col(k) = (c.row(k + 1) - c.row(0)).transpose();
  const VecX l = a.partialPivLu().solve(x - c.row(0).transpose());
  VecX w(d + 1);
  w(0) = 1.0 - l.sum();
  w.tail(d) = l;
  return w;
}

// Bilinear weights of x in the quad `c` (4 x 2, counter-clockwise), from (xi, eta) in [-1, 1]^2 found by
// Newton's method on the isoparametric map; `inside` tells whether (xi, eta) is in the reference square.
VecX bilinear(const MatX& c, const VecX& x, double tol, bool* inside) {
  const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  double xi = 0.0, eta = 0.0;
  VecX w(4);
  for (int it = 0; it < 50; ++it) {
    Vec2 r = -x;
    Eigen::Matrix2d j = Eigen::Matrix2d::Zero();
    for (int a = 0; a < 4; ++a) {
      w(a) = 0.25 * (1 + sx[a] * xi) * (1 + sy[a] * eta);
      r += w(a) * c.row(a).transpose();
      j.col(0) += 0.25 * sx[a] * (1 + sy[a] * eta) * c.row(a).transpose();
      j.col(1) += 0.25 * sy[a] * (1 + sx[a] * xi) * c.row(a).transpose();
    }
    if (r.norm() < 1e-14 * (1.0 + c.norm())) break;
    const Vec2 step = j.partialPivLu().solve(r);
    xi -= step(0);
    eta -= step(1);
    if (std::abs(xi) > 10.0 || std::abs(eta) > 10.0) break;  // far outside: stop early
  }
  for (int a = 0; a < 4; ++a) w(a) = 0.25 * (1 + sx[a] * xi) * (1 + sy[a] * eta);
  *inside = std::abs(xi) <= 1.0 + tol && std::abs(eta) <= 1.0 + tol;
  return w;
}

}  // namespace

RowMatX interpolate_nodal(const Mesh& mesh, const RowMatX& values, const RowMatX& points) {
  if (mesh.kind == ElementKind::kSurfaceTriangle) throw InvalidArgument("interpolation needs a volume or planar mesh");
  if (values.rows() != mesh.node_count()) throw InvalidArgument("interpolate_nodal: one value row per node");
  const int d = mesh.dim(), npe = static_cast<int>(mesh.elements.cols());
  if (points.cols() != d) throw InvalidArgument("interpolate_nodal: points must have the mesh's dimension");
  const double tol = 1e-9;
  const double scale = bounding_box_diagonal(mesh);
  RowMatX out(points.rows(), values.cols());
  for (Eigen::Index p = 0; p < points.rows(); ++p) {
    const VecX x = points.row(p).transpose();
    bool found = false;
    for (int e = 0; e < mesh.element_count() && !found; ++e) {
      MatX c(npe, d);
      for (int a = 0; a < npe; ++a) c.row(a) = mesh.nodes.row(mesh.elements(e, a));
      // Cheap rejection by the element's bounding box.
      if (((x.transpose().array() < c.colwise().minCoeff().array() - tol * scale) ||
           (x.transpose().array() > c.colwise().maxCoeff().array() + tol * scale))
              .any())
        continue;
      VecX w;
      if (mesh.kind == ElementKind::kQuad) {
        bool inside = false;
        w = bilinear(c, x, 1e-9, &inside);
        if (!inside) continue;
      } else {
        w = barycentric(c, x);
        if (w.minCoeff() < -1e-9) continue;
      }
      out.row(p).setZero();
      for (int a = 0; a < npe; ++a) out.row(p) += w(a) * values.row(mesh.elements(e, a));
      found = true;
    }
    if (!found)
      throw InvalidArgument("point " + std::to_string(p) + " lies in no element of " +
                            (mesh.source.empty() ? std::string("the mesh") : mesh.source));
  }
  return out;
}

}  // namespace hooke::mesh
