// model/support: the one rule for supports and loaded regions, checked on meshes whose ends are known by
// construction (a box grid, a cylinder, a cube surface).
#include <gtest/gtest.h>

#include <hooke/mesh/generators.hpp>
#include <hooke/model/support.hpp>

namespace hooke::model {
namespace {

TEST(EndNodes, FaceOfABoxGridIsOneLayerOfNodes) {
  const mesh::Mesh box = mesh::tet_box(0.02, 0.03, 0.04, 2, 3, 4);  // 3 x 4 x 5 nodes
  for (int axis = 0; axis < 3; ++axis) {
    const int layer = box.node_count() / (std::array{3, 4, 5}[static_cast<size_t>(axis)]);
    for (End end : {End::kLow, End::kHigh}) {
      const std::vector<int> nodes = end_nodes(box, axis, end, kFace);
      EXPECT_EQ(static_cast<int>(nodes.size()), layer) << axis;
      const double at = end == End::kLow ? box.nodes.col(axis).minCoeff() : box.nodes.col(axis).maxCoeff();
      for (int i : nodes) EXPECT_NEAR(box.nodes(i, axis), at, 1e-12);
    }
  }
}

TEST(EndNodes, BandTakesTheFractionOfTheExtent) {
  const mesh::Mesh box = mesh::tet_box(0.01, 0.01, 0.04, 1, 1, 8);  // layers every 5 mm along z
  // A band of 0.3 x 40 mm = 12 mm holds the layers at 0, 5 and 10 mm: 3 x 4 nodes.
  EXPECT_EQ(end_nodes(box, 2, End::kLow, 0.3).size(), 12u);
  EXPECT_EQ(end_nodes(box, 2, End::kHigh, 0.3).size(), 12u);
  EXPECT_NEAR(end_tolerance(box, 2, 0.3), 0.012, 1e-15);
  EXPECT_GT(end_tolerance(box, 2, kFace), 0.0);
  EXPECT_LT(end_tolerance(box, 2, kFace), 1e-7);
}

TEST(EndFacets, TopFaceOfABoxCarriesItsArea) {
  const mesh::Mesh box = mesh::tet_box(0.02, 0.03, 0.04, 2, 3, 4);
  const BoundaryFacets b = boundary_facets_with_geometry(box);
  const std::vector<int> top = end_facets(box, b.facets, 2, End::kHigh, kFace);
  double area = 0.0;
  for (int f : top) area += b.measures(f);
  EXPECT_NEAR(area, 0.02 * 0.03, 1e-15);
  // The facets facing +z in the top quarter are the same ones: the sides' normals are horizontal.
  EXPECT_EQ(facing_end_facets(box, b, 2, End::kHigh, 0.25), top);
}

TEST(BoundaryFacets, NormalsPointOutward) {
  const mesh::Mesh box = mesh::tet_box(0.02, 0.03, 0.04, 2, 3, 4);
  const BoundaryFacets b = boundary_facets_with_geometry(box);
  const Vec3 centre(0.01, 0.015, 0.02);
  for (Eigen::Index f = 0; f < b.facets.rows(); ++f) {
    EXPECT_NEAR(b.normals.row(f).norm(), 1.0, 1e-12);
    EXPECT_GT(b.normals.row(f).dot(b.centroids.row(f) - centre.transpose()), 0.0);
  }
}

TEST(FacingEndFacets, SidesOfACylinderFaceNeitherEnd) {
  // The side facets' normals are horizontal: within the lowest half, only the bottom disc faces -z.
  const mesh::Mesh cyl = mesh::tet_cylinder(0.01, 0.02, 12, 4);
  const BoundaryFacets b = boundary_facets_with_geometry(cyl);
  const std::vector<int> low = facing_end_facets(cyl, b, 2, End::kLow, 0.5);
  EXPECT_EQ(low, end_facets(cyl, b.facets, 2, End::kLow, kFace));
  EXPECT_FALSE(low.empty());
  for (int f : low) EXPECT_LT(b.normals(f, 2), -0.5);
  // A band of the whole height still leaves the sides out, and the top faces +z, not -z.
  EXPECT_EQ(facing_end_facets(cyl, b, 2, End::kLow, 1.0), low);
}

}  // namespace
}  // namespace hooke::model
