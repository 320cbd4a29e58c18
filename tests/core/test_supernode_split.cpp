// detail::split_supernodes: two groups of independent subtrees of a supernodal elimination tree.
#include <gtest/gtest.h>

#include <hooke/core/detail/supernode_split.hpp>
#include <vector>

namespace hooke::detail {
namespace {

// One column per supernode, a nested-dissection tree in postorder: 6 is the root separator over {2 <- 0, 1} and
// {5 <- 3, 4}. Rows: each column's own, then its parent's (and, for 0 and 3, the root's too).
struct Tree {
  std::vector<int> super{0, 1, 2, 3, 4, 5, 6, 7};
  std::vector<int> pi{0}, rows;
  explicit Tree(const std::vector<std::vector<int>>& column_rows = {
                    {0, 2, 6}, {1, 2}, {2, 6}, {3, 5, 6}, {4, 5}, {5, 6}, {6}}) {
    for (const auto& c : column_rows) {
      rows.insert(rows.end(), c.begin(), c.end());
      pi.push_back(static_cast<int>(rows.size()));
    }
  }
  SupernodeSplit split(long long min_entries = 0) const {
    return split_supernodes(7, super.data(), pi.data(), rows.data(), min_entries);
  }
};

TEST(SupernodeSplit, SplitsBelowTheRootSeparator) {
  const SupernodeSplit s = Tree().split();
  ASSERT_TRUE(s.parallel());
  using Ranges = std::vector<std::array<int, 2>>;
  EXPECT_EQ(s.ranges[0], (Ranges{{0, 2}}));
  EXPECT_EQ(s.ranges[1], (Ranges{{3, 5}}));
  EXPECT_EQ(s.top, std::vector<int>{6});
  EXPECT_EQ(s.top_columns, std::vector<int>{6});
}

TEST(SupernodeSplit, StaysSerialWhenSmallUnevenOrNotPostordered) {
  EXPECT_FALSE(Tree().split(1000).parallel());  // fewer entries than asked for
  // A path 0 <- 1 <- ... <- 6: no two independent subtrees without opening most of it.
  EXPECT_FALSE(Tree({{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6}, {6}}).split().parallel());
  // 1's parent is 5: the subtrees of 2 and 5 interleave (not a postorder).
  EXPECT_FALSE(Tree({{0, 2, 6}, {1, 5}, {2, 6}, {3, 5, 6}, {4, 5}, {5, 6}, {6}}).split().parallel());
}

}  // namespace
}  // namespace hooke::detail
