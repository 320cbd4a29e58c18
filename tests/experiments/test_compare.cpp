// Comparisons across resolutions, force-displacement curves and figure data.
#include <gtest/gtest.h>

#include <hooke/calibrate/model_factory.hpp>
#include <hooke/experiments/compare.hpp>
#include <hooke/experiments/figure.hpp>
#include <hooke/experiments/force_displacement.hpp>
#include <hooke/mesh/generators.hpp>
#include <iostream>

namespace hooke::experiments {
namespace {

using material::Law;
using material::Material;
using material::Plane;

const Material kThird{Law::kLinear, 14630.0, 1.0 / 3.0, Plane::kStress, 0.001};

// With the same mesh on both sides, compare_across is compare.
TEST(CompareAcross, SameMeshIsPlainCompare) {
  const mesh::Mesh m = mesh::rectangle_quads(0.05, 0.05, 4, 4);
  CompareOptions o;
  o.method = calibrate::Method::kLloydSquare;
  o.load = model::LoadKind::kShear;
  o.strain = 0.12;
  const Comparison a = compare(m, {kThird}, o), b = compare_across(m, m, kThird, o);
  EXPECT_NEAR(a.max_error, b.max_error, 1e-12);
  EXPECT_NEAR(a.mean_error, b.mean_error, 1e-12);
}

// Lloyd Sec. 5.4: coarse Eq. 10-11 models against the FEM at the finest resolution. Coarse nodes that lie on
// fine nodes get the fine FEM's own positions; the error shrinks as the spring model is refined.
TEST(CompareAcross, CoarseSpringModelsAgainstTheFineFem) {
  const mesh::Mesh fine = mesh::rectangle_quads(0.05, 0.05, 8, 8), coarse = mesh::rectangle_quads(0.05, 0.05, 2, 2);
  CompareOptions o;
  o.method = calibrate::Method::kLloydSquare;
  o.load = model::LoadKind::kStretch;
  o.strain = 0.05;
  const Comparison c = compare_across(coarse, fine, kThird, o), f = compare_across(fine, fine, kThird, o);
  ASSERT_EQ(c.fem_positions.size(), 2 * coarse.node_count());
  EXPECT_EQ(c.fem_mesh_positions.size(), 2 * fine.node_count());
  // Coarse node 4 (centre, 2.5 cm, 2.5 cm) is fine node 4 * 9 + 4 = 40.
  EXPECT_NEAR((c.fem_positions.segment<2>(8) - c.fem_mesh_positions.segment<2>(80)).norm(), 0.0, 1e-14);
  std::cout << "[resolution] 4 squares: max " << c.max_error << " m, 64 squares: max " << f.max_error << " m\n";
  EXPECT_GT(c.max_error, f.max_error);
}

// Lloyd Fig. 1: at small forces the Eq. 8 triangle is exactly as stiff as the CST (nu = 1/3); at large ones it
// is stiffer in stretch than in compression.
TEST(ForceDisplacement, TriangleLinearAtSmallForcesAndSofterInCompression) {
  const Material mat{Law::kLinear, 1000.0, 1.0 / 3.0, Plane::kStress, 0.01};
  const mesh::Mesh tri = mesh::equilateral_membrane(2, 2, 1.0);
  const ForceDisplacement small =
      force_displacement(tri, mat, calibrate::Method::kLloydEquilateral, {-1e-5, -5e-6, 5e-6, 1e-5});
  EXPECT_NEAR(small.stretch_stiffness / small.fem_stiffness, 1.0, 1e-4);
  EXPECT_NEAR(small.compress_stiffness / small.fem_stiffness, 1.0, 1e-4);
  EXPECT_NEAR(small.fem_stiffness, 3.0 * std::sqrt(3.0) / 8.0 * 10.0, 1e-9);  // two springs at 60 degrees
  const ForceDisplacement large = force_displacement(tri, mat, calibrate::Method::kLloydEquilateral, {-1.2, 1.2});
  EXPECT_GT(large.stretch_stiffness, large.fem_stiffness);
  EXPECT_LT(large.compress_stiffness, large.fem_stiffness);
}

TEST(Figure, DrawingEdgesAreElementEdgesIn2DAndTheSurfaceIn3D) {
  EXPECT_EQ(drawing_edges(mesh::equilateral_membrane(7, 6, 0.01)).size(), 92u);
  EXPECT_EQ(drawing_edges(mesh::rectangle_quads(1, 1, 5, 5)).size(), 60u);  // no diagonals
  // 2 x 2 x 2 tet box: each face 2 x 2 squares split into triangles: 12 + 8 edges per face, shared edges once.
  const auto e = drawing_edges(mesh::tet_box(1, 1, 1, 2, 2, 2));
  const mesh::Mesh box = mesh::tet_box(1, 1, 1, 2, 2, 2);
  for (const auto& ij : e)  // every drawn edge lies on the box's surface
    EXPECT_TRUE((box.nodes.row(ij[0]).array() == 0.0 || box.nodes.row(ij[0]).array() == 1.0).any());
  EXPECT_EQ(e.size(), 6u * 8u + 12u * 2u);
}

// The surface model against the FEM of its radially tetrahedralised volume: both see the same total load at the
// same surface nodes, both solves converge, the FEM positions are those of the tet mesh's boundary nodes, and the
// surface model moves the loaded face the same way as the FEM (compression: down).
TEST(CompareSurface, SameLoadsOnBothAndTheSameSense) {
  const mesh::Mesh cube = mesh::cube_surface(4, 0.1);
  CompareOptions o;
  o.load = model::LoadKind::kCompress;
  o.strain = 0.02;
  const Comparison c = compare_surface(cube, {Law::kLinear, 3250.0, 0.3}, {}, o, 3);
  ASSERT_EQ(c.fem_report.status, solve::SolveStatus::kConverged);
  ASSERT_EQ(c.spring_report.status, solve::SolveStatus::kConverged);
  const int n = cube.node_count(), offset = 1 + 2 * n;
  EXPECT_EQ(c.fem_positions, c.fem_mesh_positions.segment(3 * offset, 3 * n));
  double total = 0.0;
  for (Eigen::Index i = 2; i < c.load.nodal_forces.size(); i += 3) total += c.load.nodal_forces(i);
  EXPECT_NEAR(total, -c.load.traction_pa * 0.01, 1e-9 * c.load.traction_pa);  // over the 0.1 m x 0.1 m face
  ASSERT_FALSE(c.load.top_nodes.empty());
  for (int i : c.load.top_nodes) {
    EXPECT_LT(c.fem_positions(3 * i + 2), cube.nodes(i, 2));
    EXPECT_LT(c.spring_positions(3 * i + 2), cube.nodes(i, 2));
  }
  std::cout << "[compare-surface] compress 2 %: max error " << c.max_error * 1e3 << " mm, mean " << c.mean_error * 1e3
            << " mm\n";
  EXPECT_GT(c.max_error, 0.0);
}

// The three load cases at once (what certify runs: one FEM factorisation, one solver for the model's loads) give
// the comparisons of separate calls, for a spring model with volume terms and for Arnab & Raja's surface model.
TEST(CompareCalibratedCases, EqualSeparateComparisons) {
  calibrate::ModelOptions springs;
  springs.method = "stiffness-fit-volume";
  calibrate::ModelOptions surface;
  surface.method = "surface";
  const Material mat{Law::kLinear, 3250.0, 0.45};
  const calibrate::CalibratedModel models[] = {
      calibrate::calibrate_model(mesh::tet_box(0.01, 0.01, 0.02, 3, 3, 5), mat, springs),
      calibrate::calibrate_model(mesh::cube_surface(4, 0.1), {Law::kLinear, 3250.0, 0.3}, surface)};
  for (const calibrate::CalibratedModel& model : models) {
    // The surface model on this coarse cube finds no stretched equilibrium at any load factor, in separate calls as
    // well (Newton on its approximate Hessian): compression and shear only.
    const std::vector<model::LoadKind> kinds =
        model.surface ? std::vector<model::LoadKind>{model::LoadKind::kCompress, model::LoadKind::kShear}
                      : std::vector<model::LoadKind>{model::LoadKind::kStretch, model::LoadKind::kCompress,
                                                     model::LoadKind::kShear};
    CompareOptions o;
    o.strain = 0.01;
    o.load_steps = 1;
    const std::vector<Comparison> together = compare_calibrated_cases(model, kinds, o, 3);
    ASSERT_EQ(together.size(), kinds.size());
    for (size_t k = 0; k < kinds.size(); ++k) {
      o.load = kinds[k];
      const Comparison one = compare_calibrated(model, o, 3);
      EXPECT_EQ(together[k].load.kind, kinds[k]);
      EXPECT_NEAR(together[k].load.traction_pa, one.load.traction_pa, 1e-12 * one.load.traction_pa);
      EXPECT_NEAR(together[k].relative_l2, one.relative_l2, 1e-8 * one.relative_l2) << model.method << " " << k;
      EXPECT_NEAR(together[k].max_error, one.max_error, 1e-8 * one.max_error);
      EXPECT_EQ(together[k].spring_report.status, solve::SolveStatus::kConverged)
          << model.method << " " << k << ": " << together[k].spring_report.message
          << " | separately: " << one.spring_report.message;
      EXPECT_GT(together[k].relative_l2, 0.0);
    }
  }
}

}  // namespace
}  // namespace hooke::experiments
