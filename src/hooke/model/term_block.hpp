#pragma once
/// One batch of energy terms of a model (all FEM elements, all springs, ...), evaluated in one call.
#include <hooke/core/types.hpp>
#include <string_view>
#include <vector>

namespace hooke::model {

/// Interface of a term block. Positions x are flat and node-major: x[dim * node + axis], m.
/// One virtual call per block and evaluation, never per element.
class TermBlock {
 public:
  virtual ~TermBlock() = default;
  /// Stable name for reports ("fem", "springs", ...).
  virtual std::string_view name() const = 0;
  /// Stored elastic energy at x, J. +infinity where x is outside the block's domain (an inverted element).
  virtual double energy(const Eigen::Ref<const VecX>& x) const = 0;
  /// Adds dE/dx at x (N) to `gradient` (same size as x).
  virtual void add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const = 0;
  /// Appends the entries of d2E/dx2 at x (N/m) to `triplets` (duplicates are summed on assembly).
  /// @param project_psd  project each element's Hessian to positive semi-definite first
  virtual void add_hessian(const Eigen::Ref<const VecX>& x, std::vector<Triplet>& triplets, bool project_psd) const = 0;
};

}  // namespace hooke::model
