// Reverse Cuthill-McKee: a permutation, and a small bandwidth even from a shuffled numbering.
#include <gtest/gtest.h>

#include <algorithm>
#include <hooke/core/error.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/reorder.hpp>
#include <iostream>
#include <numeric>
#include <random>

namespace hooke::mesh {
namespace {

Mesh shuffled(const Mesh& m, unsigned seed) {
  std::vector<int> order(static_cast<size_t>(m.node_count()));
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(seed));
  return permute_nodes(m, order);
}

TEST(Reorder, RcmIsAPermutationWithASmallBandwidth) {
  const Mesh m = shuffled(tet_cylinder(0.01, 0.02, 10, 8), 3);
  const std::vector<int> order = rcm_order(m);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> identity(static_cast<size_t>(m.node_count()));
  std::iota(identity.begin(), identity.end(), 0);
  ASSERT_EQ(sorted, identity);
  const Mesh r = permute_nodes(m, order);
  // Same geometry per element.
  for (int e = 0; e < m.element_count(); e += 97)
    for (int a = 0; a < 4; ++a) EXPECT_EQ(r.nodes.row(r.elements(e, a)), m.nodes.row(m.elements(e, a)));
  std::cout << "bandwidth: shuffled " << node_bandwidth(m) << ", rcm " << node_bandwidth(r) << ", generator "
            << node_bandwidth(tet_cylinder(0.01, 0.02, 10, 8)) << " (" << m.node_count() << " nodes)\n";
  EXPECT_LT(node_bandwidth(r), node_bandwidth(m) / 5);
  EXPECT_LE(node_bandwidth(r), 2 * node_bandwidth(tet_cylinder(0.01, 0.02, 10, 8)));
}

TEST(Reorder, IsolatedNodesComeLastAndBadPermutationsAreRejected) {
  Mesh m = tet_box(0.01, 0.01, 0.01, 1, 1, 1);
  m.nodes.conservativeResize(m.node_count() + 1, 3);
  m.nodes.row(m.node_count() - 1).setZero();
  EXPECT_EQ(rcm_order(m).back(), m.node_count() - 1);
  EXPECT_THROW(permute_nodes(m, std::vector<int>(static_cast<size_t>(m.node_count()), 0)), InvalidArgument);
}

}  // namespace
}  // namespace hooke::mesh
