#include <algorithm>
#include <hooke/core/detail/supernode_split.hpp>
#include <numeric>

namespace hooke::detail {

SupernodeSplit split_supernodes(int nsuper, const int* super, const int* pi, const int* rows, long long min_entries) {
  const auto ns = static_cast<size_t>(nsuper);
  std::vector<long long> own(ns), sub(ns);
  long long total = 0;
  for (size_t s = 0; s < ns; ++s) {
    own[s] = static_cast<long long>(pi[s + 1] - pi[s]) * (super[s + 1] - super[s]);
    total += own[s];
  }
  if (nsuper < 2 || total < min_entries) return {};
  // The tree: a supernode's parent holds its first row below its own columns.
  const int n = super[nsuper];
  std::vector<int> owner(static_cast<size_t>(n)), parent(ns, -1), first(ns), size(ns, 1);
  for (size_t s = 0; s < ns; ++s)
    for (int k = super[s]; k < super[s + 1]; ++k) owner[static_cast<size_t>(k)] = static_cast<int>(s);
  for (size_t s = 0; s < ns; ++s) {
    const int columns = super[s + 1] - super[s];
    if (pi[s + 1] - pi[s] > columns) parent[s] = owner[static_cast<size_t>(rows[pi[s] + columns])];
    if (parent[s] >= 0 && parent[s] <= static_cast<int>(s)) return {};
  }
  std::iota(first.begin(), first.end(), 0);
  sub = own;
  for (size_t s = 0; s < ns; ++s)
    if (const int p = parent[s]; p >= 0) {
      first[static_cast<size_t>(p)] = std::min(first[static_cast<size_t>(p)], first[s]);
      size[static_cast<size_t>(p)] += size[s];
      sub[static_cast<size_t>(p)] += sub[s];
    }
  for (size_t s = 0; s < ns; ++s)  // postorder: every subtree a contiguous range ending at its root
    if (first[s] != static_cast<int>(s) - size[s] + 1) return {};
  std::vector<std::vector<int>> children(ns);
  std::vector<int> frontier;
  for (size_t s = 0; s < ns; ++s)
    (parent[s] >= 0 ? children[static_cast<size_t>(parent[s])] : frontier).push_back(static_cast<int>(s));

  // Open the heaviest subtree of the frontier (its root joins the top) until its subtrees split evenly in two.
  long long top_work = 0;
  std::array<std::vector<int>, 2> bins;
  for (;;) {
    std::sort(frontier.begin(), frontier.end(), [&](int a, int b) {
      return sub[static_cast<size_t>(a)] != sub[static_cast<size_t>(b)]
                 ? sub[static_cast<size_t>(a)] > sub[static_cast<size_t>(b)]
                 : a < b;
    });
    std::array<long long, 2> load{};
    bins = {};
    for (int f : frontier) {  // greedy: the next heaviest subtree to the lighter group
      const int g = load[1] < load[0] ? 1 : 0;
      bins[static_cast<size_t>(g)].push_back(f);
      load[static_cast<size_t>(g)] += sub[static_cast<size_t>(f)];
    }
    const long long sum = load[0] + load[1];
    if (sum > 0 && 10 * std::max(load[0], load[1]) <= 6 * sum) break;
    const int heaviest = frontier.front();
    if (children[static_cast<size_t>(heaviest)].empty()) return {};
    top_work += own[static_cast<size_t>(heaviest)];
    if (100 * top_work > 25 * total) return {};
    frontier.erase(frontier.begin());
    frontier.insert(frontier.end(), children[static_cast<size_t>(heaviest)].begin(),
                    children[static_cast<size_t>(heaviest)].end());
  }

  SupernodeSplit split;
  std::vector<char> covered(ns, 0);
  for (size_t g = 0; g < 2; ++g) {
    for (int f : bins[g]) {
      split.ranges[g].push_back({first[static_cast<size_t>(f)], f});
      std::fill(covered.begin() + first[static_cast<size_t>(f)], covered.begin() + f + 1, 1);
    }
    std::sort(split.ranges[g].begin(), split.ranges[g].end());
  }
  for (size_t s = 0; s < ns; ++s)
    if (!covered[s]) {
      split.top.push_back(static_cast<int>(s));
      for (int k = super[s]; k < super[s + 1]; ++k) split.top_columns.push_back(k);
    }
  return split;
}

}  // namespace hooke::detail
