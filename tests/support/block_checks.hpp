#pragma once
// The derivative check every term block gets: gradient = central differences of the energy, Hessian =
// central differences of the gradient (docs/architecture.md, independent checks); and the one-pass
// energy_and_add_gradient = the two calls.
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

// energy_and_add_gradient adds the gradient to what `gradient` holds and returns the energy: both as the separate
// calls give them (to round-off: a fused loop may sum in another order).
inline void expect_fused_energy_and_gradient(const model::TermBlock& b, const VecX& x) {
  const VecX offset = VecX::LinSpaced(x.size(), -1.0, 2.0);
  VecX g = offset;
  const double e = b.energy_and_add_gradient(x, g);
  const double e_ref = b.energy(x);
  const VecX g_ref = block_gradient(b, x);
  EXPECT_NEAR(e, e_ref, 1e-13 * std::abs(e_ref) + 1e-300) << b.name() << " fused energy";
  EXPECT_LT((g - offset - g_ref).norm(), 1e-12 * (g_ref.norm() + offset.norm())) << b.name() << " fused gradient";
}

// Relative tolerance `tol` on both, finite-difference step h (m); dim 2 or 3.
inline void expect_derivatives_match_finite_differences(const model::TermBlock& b, int dim, const VecX& x, double h,
                                                        double tol) {
  const VecX g = block_gradient(b, x);
  const VecX g_fd = fd_gradient([&](const VecX& y) { return b.energy(y); }, x, h);
  EXPECT_LT((g - g_fd).norm(), tol * g.norm()) << b.name() << " gradient";
  const MatX h_fd = fd_jacobian([&](const VecX& y) { return block_gradient(b, y); }, x, h);
  EXPECT_LT((block_hessian(b, dim, x) - h_fd).norm(), tol * h_fd.norm()) << b.name() << " Hessian";
  expect_fused_energy_and_gradient(b, x);
}

}  // namespace hooke::test
