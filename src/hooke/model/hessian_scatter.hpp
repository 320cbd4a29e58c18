#pragma once
/// Where each element's Hessian entries go in the value array of a matrix with a fixed sparsity pattern.
#include <hooke/core/types.hpp>
#include <vector>

namespace hooke::model {

/// Built once per term block by HessianAssembly from the block's element_nodes(). The pattern holds a full
/// dim x dim block for every pair of nodes that share an element, in compressed column storage; the entry
/// (dim n_a + i, dim n_b + k) of element e is at base(e, a, b) + k * stride(e, b) + i.
struct HessianScatter {
  int dim = 0;
  int nodes_per_element = 0;
  std::vector<int> base;    ///< per element, per node pair (a, b), a-major: value index of (dim n_a, dim n_b)
  std::vector<int> stride;  ///< per element, per node b: value distance between consecutive columns of n_b

  /// Adds the element Hessian h (D N x D N, node-major) of element e into values. @pre D == dim, N == npe
  template <int D, int N>
  void add(int e, const Eigen::Matrix<double, D * N, D * N>& h, double* values) const {
    const int* b0 = base.data() + static_cast<size_t>(e) * N * N;
    const int* s0 = stride.data() + static_cast<size_t>(e) * N;
    for (int b = 0; b < N; ++b)
      for (int k = 0; k < D; ++k)
        for (int a = 0; a < N; ++a) {
          double* column = values + b0[a * N + b] + k * s0[b];
          for (int i = 0; i < D; ++i) column[i] += h(D * a + i, D * b + k);
        }
  }
};

}  // namespace hooke::model
