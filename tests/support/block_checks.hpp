#pragma once
// The derivative check every term block gets: gradient = central differences of the energy, Hessian =
// central differences of the gradient (STYLE.md, Tests).
#include <gtest/gtest.h>

#include <hooke/model/hessian_assembly.hpp>
#include <support/finite_difference.hpp>

namespace hooke::test {

inline VecX block_gradient(const model::TermBlock& b, const VecX& x) {
  VecX g = VecX::Zero(x.size());
  b.add_gradient(x, g);
  return g;
}

inline MatX block_hessian(const model::TermBlock& b, int dim, const VecX& x, bool project_psd = false) {
  return MatX(model::block_hessian(b, dim, x, project_psd));
}

// Relative tolerance `tol` on both, finite-difference step h (m); dim 2 or 3.
inline void expect_derivatives_match_finite_differences(const model::TermBlock& b, int dim, const VecX& x, double h,
                                                        double tol) {
  const VecX g = block_gradient(b, x);
  const VecX g_fd = fd_gradient([&](const VecX& y) { return b.energy(y); }, x, h);
  EXPECT_LT((g - g_fd).norm(), tol * g.norm()) << b.name() << " gradient";
  const MatX h_fd = fd_jacobian([&](const VecX& y) { return block_gradient(b, y); }, x, h);
  EXPECT_LT((block_hessian(b, dim, x) - h_fd).norm(), tol * h_fd.norm()) << b.name() << " Hessian";
}

}  // namespace hooke::test
