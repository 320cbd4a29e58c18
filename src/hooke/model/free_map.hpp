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
  /// The free rows and columns of `full` (dof_count square), its stored entries kept as they are. One pass, no
  /// triplets: free indices increase with full ones, so each kept column's rows stay sorted (the triplet build took
  /// 0.8 s on a scan's 9 M entries).
  SparseMatrix restrict(const SparseMatrix& full) const {
    SparseMatrix r(size(), size());
    Eigen::Index nnz = 0;
    for (const int col : free)
      for (SparseMatrix::InnerIterator it(full, col); it; ++it) nnz += to_free[static_cast<size_t>(it.row())] >= 0;
    r.resizeNonZeros(nnz);
    int* outer = r.outerIndexPtr();
    int* inner = r.innerIndexPtr();
    double* value = r.valuePtr();
    int k = 0;
    for (int fc = 0; fc < size(); ++fc) {
      outer[fc] = k;
      for (SparseMatrix::InnerIterator it(full, free[static_cast<size_t>(fc)]); it; ++it)
        if (const int fr = to_free[static_cast<size_t>(it.row())]; fr >= 0) {
          inner[k] = fr;
          value[k++] = it.value();
        }
    }
    outer[size()] = k;
    return r;
  }
};

}  // namespace hooke::model
