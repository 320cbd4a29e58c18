// ElementSchedule: which elements two threads may visit at once.
#include <gtest/gtest.h>

#include <omp.h>
#include <algorithm>
#include <hooke/core/element_schedule.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/reorder.hpp>
#include <numeric>
#include <random>
#include <set>

namespace hooke {
namespace {

// Every element visited once, and the chunks of one phase (same parity) touch pairwise disjoint node sets, checked
// from the chunks' node sets themselves.
void expect_valid(const ElementSchedule& s, const RowMatXi& elements) {
  std::vector<std::vector<int>> chunks(static_cast<size_t>(s.chunk_count()));
  s.for_each_chunk([&](std::span<const int> e, int c) { chunks[static_cast<size_t>(c)].assign(e.begin(), e.end()); });
  std::vector<int> visits(static_cast<size_t>(elements.rows()), 0);
  std::vector<std::set<int>> nodes(chunks.size());
  for (size_t c = 0; c < chunks.size(); ++c)
    for (int e : chunks[c]) {
      ++visits[static_cast<size_t>(e)];
      for (Eigen::Index a = 0; a < elements.cols(); ++a) nodes[c].insert(elements(e, a));
    }
  EXPECT_TRUE(std::all_of(visits.begin(), visits.end(), [](int v) { return v == 1; }));
  for (size_t c = 0; c < chunks.size(); ++c)
    for (size_t d = c + 2; d < chunks.size(); d += 2)
      for (int node : nodes[c]) ASSERT_EQ(nodes[d].count(node), 0u) << "chunks " << c << " and " << d;
}

// A banded mesh keeps its node-order schedule; the same mesh with its nodes shuffled (as a tetrahedraliser numbers
// them: no locality) is still split for two threads, by breadth-first ranks, and validly.
TEST(ElementSchedule, SplitsBandedAndShuffledMeshesForTwoThreads) {
  const mesh::Mesh box = mesh::tet_box(0.04, 0.01, 0.01, 24, 6, 6);
  ASSERT_GE(box.element_count(), 4096);
  const ElementSchedule banded(box.elements);
  EXPECT_TRUE(banded.parallel());
  expect_valid(banded, box.elements);

  std::vector<int> shuffle(static_cast<size_t>(box.node_count()));
  std::iota(shuffle.begin(), shuffle.end(), 0);
  std::shuffle(shuffle.begin(), shuffle.end(), std::mt19937(3));
  const mesh::Mesh shuffled = mesh::permute_nodes(box, shuffle);
  const ElementSchedule s(shuffled.elements);
  EXPECT_TRUE(s.parallel());
  expect_valid(s, shuffled.elements);

  // The visiting order, so a sum's rounding, does not depend on the number of threads.
  auto f = [&](int e) { return 1.0 / (1.0 + e) + shuffled.elements(e, 0) * 1e-7; };
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const double one = s.sum(f);
  omp_set_num_threads(2);
  const double two = s.sum(f);
  omp_set_num_threads(threads);
  EXPECT_EQ(one, two);
}

}  // namespace
}  // namespace hooke
