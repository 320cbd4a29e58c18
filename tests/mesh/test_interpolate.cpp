// Interpolation of nodal fields: exact for fields the shape functions contain, errors for points outside.
#include <gtest/gtest.h>

#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/interpolate.hpp>

namespace hooke::mesh {
namespace {

// f(x) = A x + b, two components, sampled at the nodes.
RowMatX affine(const RowMatX& x) {
  RowMatX f(x.rows(), 2);
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    f(i, 0) = 0.3 + 2.0 * x(i, 0) - 1.5 * x(i, 1) + (x.cols() == 3 ? 0.7 * x(i, 2) : 0.0);
    f(i, 1) = -1.0 + 0.5 * x(i, 0) + 4.0 * x(i, 1);
  }
  return f;
}

RowMatX sample_points(int n, int dim, double lo, double hi) {
  RowMatX p(n, dim);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < dim; ++k) p(i, k) = lo + (hi - lo) * (0.5 + 0.5 * std::sin(1.7 * i + 2.3 * k + 0.4));
  return p;
}

TEST(Interpolate, AffineFieldsAreExactOnTrianglesQuadsAndTets) {
  Mesh quads = rectangle_quads(1.0, 1.0, 3, 3);
  for (int i = 0; i < quads.node_count(); ++i)  // distort the interior nodes: still exact for affine fields
    if (quads.nodes(i, 0) > 0.01 && quads.nodes(i, 0) < 0.99 && quads.nodes(i, 1) > 0.01 && quads.nodes(i, 1) < 0.99)
      quads.nodes(i, 0) += 0.05 * std::sin(3.0 * i);
  for (const Mesh& m : {rectangle_triangles(1.0, 1.0, 3, 4), quads, tet_box(1.0, 1.0, 1.0, 2, 2, 2)}) {
    const RowMatX pts = sample_points(40, m.dim(), 0.0, 1.0);
    const RowMatX got = interpolate_nodal(m, affine(m.nodes), pts);
    EXPECT_LT((got - affine(pts)).cwiseAbs().maxCoeff(), 1e-12) << element_kind_name(m.kind);
    // At the nodes themselves, the nodal values come back.
    EXPECT_LT((interpolate_nodal(m, affine(m.nodes), m.nodes) - affine(m.nodes)).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(Interpolate, BilinearFieldIsExactOnRectangularQuads) {
  const Mesh m = rectangle_quads(2.0, 1.0, 4, 2);
  auto f = [](const RowMatX& x) {
    RowMatX v(x.rows(), 1);
    for (Eigen::Index i = 0; i < x.rows(); ++i) v(i, 0) = x(i, 0) * x(i, 1);
    return v;
  };
  RowMatX pts(1, 2);
  pts << 0.3, 0.2;  // inside the first cell, where x y is bilinear
  EXPECT_NEAR(interpolate_nodal(m, f(m.nodes), pts)(0, 0), 0.06, 1e-14);
}

TEST(Interpolate, PointOutsideIsNamed) {
  RowMatX pts(2, 2);
  pts << 0.5, 0.5, 1.5, 0.5;
  try {
    interpolate_nodal(rectangle_triangles(1.0, 1.0, 2, 2), RowMatX::Zero(9, 1), pts);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("point 1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hooke::mesh
