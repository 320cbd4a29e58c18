// Arnab & Raja's Table 1 on the three cubes (602, 1 352, 2 402 nodes): the Young's modulus re-extracted from
// scheme D is within 2 % of the one given at every resolution; the anchors alone converge to it (the crease
// reading of the blend, docs/surface.md "Creases") and the membrane's share shrinks as the mesh is refined.
#include <gtest/gtest.h>

#include <cmath>
#include <hooke/experiments/reproduce_arnab2008.hpp>

namespace hooke::experiments {
namespace {

TEST(ArnabTable1, EveryCubeReturnsYoungsModulusWithinTwoPercent) {
  const std::vector<YoungsModulusRow> rows = arnab2008_table1(0.3, 0.1, 0.01);
  ASSERT_EQ(rows.size(), 6u);
  double previous_share = 1.0;
  for (const YoungsModulusRow& r : rows) {
    EXPECT_LE(std::abs(r.deviation_percent), 2.0) << r.nodes << " nodes, E " << r.youngs_modulus;
    EXPECT_NEAR(r.deviation_percent, 100.0 * (r.extracted_d / r.youngs_modulus - 1.0), 1e-9);
    // Without the membrane the blended anchors return E to 0.5 %: before the crease reading the edge and corner
    // nodes, blended by their averaged normals, made it -4.5 / -2.9 / -2.3 %.
    EXPECT_LE(std::abs(r.extracted_d_no_membrane / r.youngs_modulus - 1.0), 5e-3) << r.nodes << " nodes";
    const double share = r.extracted_d / r.extracted_d_no_membrane - 1.0;
    EXPECT_GT(share, 0.0) << r.nodes << " nodes";
    if (r.youngs_modulus == rows.front().youngs_modulus) {
      EXPECT_LT(share, previous_share) << r.nodes << " nodes: the membrane's share should shrink with h";
      previous_share = share;
    }
  }
}

}  // namespace
}  // namespace hooke::experiments
