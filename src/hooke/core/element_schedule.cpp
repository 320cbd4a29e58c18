#include <algorithm>
#include <array>
#include <hooke/core/element_schedule.hpp>
#include <numeric>

namespace hooke {
namespace {

// Below this many elements a pass is too short for a second thread to pay (thread wake-up ~ 5-20 us).
constexpr Eigen::Index kParallelElements = 4096;

// True when chunks c and c + 2 never share a node: with elements sorted by smallest node, chunk c touches nodes
// in [its smallest, its largest]; disjoint ranges within one parity suffice.
bool valid_split(const RowMatXi& elements, const std::vector<int>& order, const std::vector<int>& start) {
  const int chunks = static_cast<int>(start.size()) - 1;
  std::vector<int> lo(static_cast<size_t>(chunks), INT32_MAX), hi(static_cast<size_t>(chunks), -1);
  for (int c = 0; c < chunks; ++c)
    for (int k = start[static_cast<size_t>(c)]; k < start[static_cast<size_t>(c) + 1]; ++k) {
      const auto row = elements.row(order[static_cast<size_t>(k)]);
      lo[static_cast<size_t>(c)] = std::min(lo[static_cast<size_t>(c)], row.minCoeff());
      hi[static_cast<size_t>(c)] = std::max(hi[static_cast<size_t>(c)], row.maxCoeff());
    }
  for (int c = 0; c + 2 < chunks; ++c)
    if (hi[static_cast<size_t>(c)] >= lo[static_cast<size_t>(c) + 2]) return false;
  return true;
}

}  // namespace

ElementSchedule::ElementSchedule(const RowMatXi& elements) {
  const auto n = static_cast<int>(elements.rows());
  m_order.resize(static_cast<size_t>(n));
  std::iota(m_order.begin(), m_order.end(), 0);
  if (elements.cols() > 0) {
    std::vector<int> smallest(static_cast<size_t>(n));
    for (int e = 0; e < n; ++e) smallest[static_cast<size_t>(e)] = elements.row(e).minCoeff();
    std::stable_sort(m_order.begin(), m_order.end(),
                     [&](int a, int b) { return smallest[static_cast<size_t>(a)] < smallest[static_cast<size_t>(b)]; });
  }
  for (int pairs = n >= kParallelElements ? kMaxChunks / 2 : 1; pairs >= 1; pairs /= 2) {
    m_chunk_start.assign(1, 0);
    for (int c = 1; c <= 2 * pairs; ++c)
      m_chunk_start.push_back(static_cast<int>(static_cast<long long>(n) * c / (2 * pairs)));
    if (pairs == 1 || valid_split(elements, m_order, m_chunk_start)) {
      m_parallel = pairs > 1;
      return;
    }
  }
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
