#pragma once
/// The order in which a term block visits its elements, and which of them two threads may visit at once.
#include <array>
#include <hooke/core/function_ref.hpp>
#include <hooke/core/types.hpp>
#include <span>
#include <vector>

namespace hooke {

/// Elements sorted by their smallest node index and cut into 2P contiguous chunks of about equal size, such that
/// the chunks of one parity touch pairwise disjoint node sets (checked; P shrinks until it holds, P = 1 is
/// serial). Phase 0 runs the even chunks in parallel (OpenMP), then phase 1 the odd ones, so a block may scatter
/// into per-node arrays without locks or per-thread copies. With nodes in a banded order (reverse
/// Cuthill-McKee, mesh/reorder.hpp) P stays large; where the node order leaves no valid split (a tetrahedraliser's
/// numbering: surface nodes first), elements are sorted by breadth-first node ranks instead. The visiting order, and
/// so the rounding of every sum, depends on the mesh only, not on the number of threads.
class ElementSchedule {
 public:
  /// Maximum number of chunks.
  static constexpr int kMaxChunks = 32;

  ElementSchedule() = default;
  /// @param elements  #E x nodes-per-element node indices (>= 0)
  explicit ElementSchedule(const RowMatXi& elements);

  /// Calls fn(chunk_elements, chunk_index) once per non-empty chunk; chunks of one phase may run concurrently.
  void for_each_chunk(FunctionRef<void(std::span<const int>, int)> fn) const;
  /// Sum over all elements of fn(e), each chunk summed in order and the chunk sums added in chunk order. A
  /// template, so that fn is inlined into the loop (through a FunctionRef, the call per element was most of a
  /// tet-volume energy pass).
  template <class Fn>
  double sum(Fn&& fn) const {
    return sum_chunks([&](std::span<const int> elements) {
      double s = 0.0;
      for (int e : elements) s += fn(e);
      return s;
    });
  }
  /// Sum over chunks of fn(chunk_elements) (a chunk's sum, which may also scatter into per-node arrays as
  /// for_each_chunk allows), added in chunk order: the same rounding as sum() when fn sums its elements in order.
  template <class Fn>
  double sum_chunks(Fn&& fn) const {
    std::array<double, kMaxChunks> partial{};
    for_each_chunk(
        [&](std::span<const int> elements, int chunk) { partial[static_cast<size_t>(chunk)] = fn(elements); });
    double total = 0.0;
    for (int c = 0; c < chunk_count(); ++c) total += partial[static_cast<size_t>(c)];
    return total;
  }

  int chunk_count() const { return static_cast<int>(m_chunk_start.size()) - 1; }
  /// True when the chunks run on several threads (enough elements and a valid split).
  bool parallel() const { return m_parallel; }

 private:
  std::vector<int> m_order;        // element indices, sorted by smallest node
  std::vector<int> m_chunk_start;  // chunk c is m_order[m_chunk_start[c] .. m_chunk_start[c + 1])
  bool m_parallel = false;
};

}  // namespace hooke
