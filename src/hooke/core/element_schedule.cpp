#include <algorithm>
#include <array>
#include <hooke/core/element_schedule.hpp>
#include <numeric>

namespace hooke {
namespace {

// Below this many elements a pass is too short for a second thread to pay (thread wake-up ~ 5-20 us).
constexpr Eigen::Index kParallelElements = 4096;

// True when chunks c and c + 2 never share a node: with elements sorted by their smallest node rank, chunk c
// touches ranks in [its smallest, its largest]; disjoint ranges within one parity suffice. rank: a node's position in
// the order the elements were sorted by (empty: the node index itself).
bool valid_split(const RowMatXi& elements, const std::vector<int>& rank, const std::vector<int>& order,
                 const std::vector<int>& start) {
  const int chunks = static_cast<int>(start.size()) - 1;
  auto rank_of = [&](int node) { return rank.empty() ? node : rank[static_cast<size_t>(node)]; };
  std::vector<int> lo(static_cast<size_t>(chunks), INT32_MAX), hi(static_cast<size_t>(chunks), -1);
  for (int c = 0; c < chunks; ++c)
    for (int k = start[static_cast<size_t>(c)]; k < start[static_cast<size_t>(c) + 1]; ++k) {
      const auto row = elements.row(order[static_cast<size_t>(k)]);
      for (Eigen::Index a = 0; a < row.size(); ++a) {
        lo[static_cast<size_t>(c)] = std::min(lo[static_cast<size_t>(c)], rank_of(row(a)));
        hi[static_cast<size_t>(c)] = std::max(hi[static_cast<size_t>(c)], rank_of(row(a)));
      }
    }
  for (int c = 0; c + 2 < chunks; ++c)
    if (hi[static_cast<size_t>(c)] >= lo[static_cast<size_t>(c) + 2]) return false;
  return true;
}

// Breadth-first ranks of the nodes over the element graph, each connected component from a pseudo-peripheral node
// (the last node reached from its first node): nodes sharing an element get close ranks, in bands one level wide
// (Cuthill & McKee 1969, without their degree order). For meshes numbered without locality, such as a
// tetrahedraliser's (surface nodes first, interior nodes after), whose chunks would all overlap.
std::vector<int> breadth_first_ranks(const RowMatXi& elements) {
  const int nodes = elements.size() > 0 ? elements.maxCoeff() + 1 : 0;
  const auto npe = static_cast<int>(elements.cols());
  std::vector<int> start(static_cast<size_t>(nodes) + 1, 0);
  for (Eigen::Index e = 0; e < elements.rows(); ++e)
    for (int a = 0; a < npe; ++a) start[static_cast<size_t>(elements(e, a)) + 1] += npe - 1;
  for (int i = 0; i < nodes; ++i) start[static_cast<size_t>(i) + 1] += start[static_cast<size_t>(i)];
  std::vector<int> adj(static_cast<size_t>(start.back())), fill(start.begin(), start.end() - 1);
  for (Eigen::Index e = 0; e < elements.rows(); ++e)
    for (int a = 0; a < npe; ++a)
      for (int b = 0; b < npe; ++b)
        if (a != b) adj[static_cast<size_t>(fill[static_cast<size_t>(elements(e, a))]++)] = elements(e, b);
  std::vector<int> rank(static_cast<size_t>(nodes), -1), queue;
  queue.reserve(static_cast<size_t>(nodes));
  std::vector<int> seen(static_cast<size_t>(nodes), -1);  // the search (root) that last reached each node
  // Breadth-first from root over nodes not ranked yet, into queue[first..]; returns the last node reached.
  auto search = [&](int root, size_t first) {
    queue.resize(first);
    queue.push_back(root);
    seen[static_cast<size_t>(root)] = root;
    for (size_t k = first; k < queue.size(); ++k) {
      const auto v = static_cast<size_t>(queue[k]);
      for (int i = start[v]; i < start[v + 1]; ++i) {
        const int w = adj[static_cast<size_t>(i)];
        if (seen[static_cast<size_t>(w)] != root && rank[static_cast<size_t>(w)] < 0) {
          seen[static_cast<size_t>(w)] = root;
          queue.push_back(w);
        }
      }
    }
    return queue.back();
  };
  for (int i = 0; i < nodes; ++i) {
    if (rank[static_cast<size_t>(i)] >= 0) continue;
    const size_t first = queue.size();
    const int far = search(i, first);
    if (far != i) search(far, first);
    for (size_t k = first; k < queue.size(); ++k) rank[static_cast<size_t>(queue[k])] = static_cast<int>(k);
  }
  return rank;
}

}  // namespace

ElementSchedule::ElementSchedule(const RowMatXi& elements) {
  const auto n = static_cast<int>(elements.rows());
  // Elements sorted by the smallest rank of their nodes, cut into 2P chunks, P halved until the split is valid.
  auto split = [&](const std::vector<int>& rank) {
    m_order.resize(static_cast<size_t>(n));
    std::iota(m_order.begin(), m_order.end(), 0);
    if (elements.cols() > 0) {
      std::vector<int> smallest(static_cast<size_t>(n), INT32_MAX);
      for (int e = 0; e < n; ++e)
        for (Eigen::Index a = 0; a < elements.cols(); ++a)
          smallest[static_cast<size_t>(e)] =
              std::min(smallest[static_cast<size_t>(e)],
                       rank.empty() ? elements(e, a) : rank[static_cast<size_t>(elements(e, a))]);
      std::stable_sort(m_order.begin(), m_order.end(), [&](int a, int b) {
        return smallest[static_cast<size_t>(a)] < smallest[static_cast<size_t>(b)];
      });
    }
    for (int pairs = n >= kParallelElements ? kMaxChunks / 2 : 1; pairs >= 1; pairs /= 2) {
      m_chunk_start.assign(1, 0);
      for (int c = 1; c <= 2 * pairs; ++c)
        m_chunk_start.push_back(static_cast<int>(static_cast<long long>(n) * c / (2 * pairs)));
      if (pairs == 1 || valid_split(elements, rank, m_order, m_chunk_start)) {
        m_parallel = pairs > 1;
        return;
      }
    }
  };
  // The node numbering first (a banded mesh keeps the order, and the rounding, it always had); where it leaves
  // every chunk overlapping, breadth-first ranks (a scan's 345 000 tets: serial -> parallel).
  split({});
  if (!m_parallel && n >= kParallelElements) split(breadth_first_ranks(elements));
}

void ElementSchedule::for_each_chunk(FunctionRef<void(std::span<const int>, int)> fn) const {
  const int chunks = chunk_count();
  auto run = [&](int c) {
    const auto begin = static_cast<size_t>(m_chunk_start[static_cast<size_t>(c)]);
    const auto end = static_cast<size_t>(m_chunk_start[static_cast<size_t>(c) + 1]);
    if (end > begin) fn(std::span<const int>(m_order.data() + begin, end - begin), c);
  };
  for (int phase = 0; phase < 2; ++phase) {
    if (!m_parallel) {  // a serial loop: libgomp allocates for a parallel region even when its if clause is false
      for (int c = phase; c < chunks; c += 2) run(c);
      continue;
    }
#pragma omp parallel for schedule(static)
    for (int c = phase; c < chunks; c += 2) run(c);
  }
}

}  // namespace hooke
