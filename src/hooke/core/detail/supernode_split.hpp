#pragma once
// Two groups of independent subtrees of a supernodal Cholesky factor's elimination tree, for a triangular solve on
// two threads: each group's supernodes touch only their own columns and those of the common ancestors ("top").
#include <array>
#include <vector>

namespace hooke::detail {

struct SupernodeSplit {
  /// Per group, whole subtrees as postorder ranges [first, last] of supernodes, increasing.
  std::array<std::vector<std::array<int, 2>>, 2> ranges;
  /// The supernodes in no group (ancestors of the subtrees), increasing.
  std::vector<int> top;
  /// The columns of the top supernodes, increasing.
  std::vector<int> top_columns;
  /// True when the solve may run the two groups at once.
  bool parallel() const { return !ranges[0].empty() && !ranges[1].empty(); }
};

/// The split of a supernodal factor with `nsuper` supernodes (CHOLMOD's arrays: supernode s holds columns
/// super[s] .. super[s + 1] - 1 and the sorted rows rows[pi[s] .. pi[s + 1]), its own columns first). Each group
/// carries 40-60 % of the subtrees' factor entries and the top (their ancestors) at most 25 % of all (a 3D
/// mesh's top separator is dense); otherwise, or where the
/// supernodes are not in postorder, or the factor has fewer than `min_entries` entries, an empty split (serial).
SupernodeSplit split_supernodes(int nsuper, const int* super, const int* pi, const int* rows, long long min_entries);

}  // namespace hooke::detail
