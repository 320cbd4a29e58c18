#pragma once
/// Restriction of assembled matrices and vectors to the free DOFs of a problem (model::free_dofs).
#include <hooke/core/types.hpp>
#include <vector>

namespace hooke::model {

/// Map from full DOF index to free index (-1 where not free).
struct FreeMap {
  std::vector<int> free;     ///< free index -> full index
  std::vector<int> to_free;  ///< full index -> free index or -1
  /// @param free_dofs  increasing full DOF indices, each < dof_count
  FreeMap(const std::vector<int>& free_dofs, int dof_count) : free(free_dofs), to_free(dof_count, -1) {
    for (size_t i = 0; i < free.size(); ++i) to_free[static_cast<size_t>(free[i])] = static_cast<int>(i);
  }
  /// Number of free DOFs.
  int size() const { return static_cast<int>(free.size()); }
  /// The free entries of `full` (dof_count).
  VecX restrict(const VecX& full) const {
    VecX r(size());
    for (int i = 0; i < size(); ++i) r(i) = full(free[static_cast<size_t>(i)]);
    return r;
  }
  /// The free rows and columns of `full` (dof_count square).
  SparseMatrix restrict(const SparseMatrix& full) const {
    std::vector<Triplet> t;
    t.reserve(static_cast<size_t>(full.nonZeros()));
    for (int col = 0; col < full.outerSize(); ++col) {
      const int fc = to_free[static_cast<size_t>(col)];
      if (fc < 0) continue;
      for (SparseMatrix::InnerIterator it(full, col); it; ++it) {
        const int fr = to_free[static_cast<size_t>(it.row())];
        if (fr >= 0) t.emplace_back(fr, fc, it.value());
      }
    }
    SparseMatrix r(size(), size());
    r.setFromTriplets(t.begin(), t.end());
    return r;
  }
};

}  // namespace hooke::model
