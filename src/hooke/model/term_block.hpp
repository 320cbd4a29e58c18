#pragma once
/// One batch of energy terms of a model (all FEM elements, all springs, ...), evaluated in one call.
#include <array>
#include <hooke/core/types.hpp>
#include <hooke/model/hessian_scatter.hpp>
#include <hooke/model/interaction.hpp>
#include <string_view>
#include <utility>
#include <vector>

namespace hooke::model {

/// What a block of central springs, E = sum_s k_s/2 (|x_i - x_j| - l0_s)^2, offers solvers that exploit that form
/// (the local/global integrator of Liu et al. 2013). A block declares it through TermBlock::central_springs();
/// solvers never recognise a block by its type or name.
class CentralSprings {
 public:
  virtual ~CentralSprings() = default;
  /// Node pairs (i, j) of the springs.
  virtual const std::vector<std::array<int, 2>>& pairs() const = 0;
  /// k per spring, N/m.
  virtual const VecX& stiffness() const = 0;
  /// Local step: adds k l0 (x_i - x_j)/|x_i - x_j| at node i and its negative at node j, N, to `out` (size of x).
  virtual void add_rest_directions(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> out) const = 0;
};

/// Interface of a term block. Positions x are flat and node-major: x[dim * node + axis], m.
/// One virtual call per block and evaluation, never per element. energy, add_gradient and add_hessian_values
/// allocate nothing (the real-time loop of solve::Simulator relies on it) and are safe to call from several threads
/// at once: a block is immutable data.
class TermBlock {
 public:
  virtual ~TermBlock() = default;
  /// Stable name for reports ("fem", "springs", ...).
  virtual std::string_view name() const = 0;
  /// True when add_gradient is the gradient of energy (the default). A non-conservative block's forces have no
  /// potential: energy() is then only a reported measure, add_hessian_values a symmetric approximation of the
  /// force Jacobian, and solvers must not minimise the energy (they drive the force residual to zero instead).
  virtual bool conservative() const { return true; }
  /// False when add_hessian_values is an approximation (a sparse stand-in for a dense coupling, or the symmetric
  /// part of a non-conservative block's Jacobian): Newton solvers then refine their steps (default true).
  virtual bool exact_hessian() const { return conservative(); }
  /// The block as central springs, or null when it is not one (default).
  virtual const CentralSprings* central_springs() const { return nullptr; }
  /// False for a block that only marks states inadmissible (infinite energy) and adds no force (default true).
  virtual bool has_forces() const { return true; }
  /// Called by solve::Simulator with the positions x (m) it starts from and after every time step, for blocks whose
  /// energy depends on the state a step starts from (lagged friction: contact::ContactBlock::lag). A block keeps that
  /// history in state shared with its copies, like a tool's pose; default nothing. Not thread-safe with evaluations.
  virtual void end_step(const Eigen::Ref<const VecX>& x) const { (void)x; }
  /// For a block whose stiffness appears and vanishes with the state on a few nodes of a 3D body (contact): appends
  /// (node, its 3 x 3 positive semi-definite Hessian block at x, N/m) for every node where that block is not zero
  /// and returns true. The quasi-Newton path adds them to its initial Hessian, which the rest Hessian alone would
  /// leave without them (docs/contact.md). Default false: nothing appended.
  virtual bool add_node_stiffness(const Eigen::Ref<const VecX>& x, std::vector<std::pair<int, Mat3>>& out) const {
    (void)x;
    (void)out;
    return false;
  }
  /// Stored elastic energy at x, J. +infinity where x is outside the block's domain (an inverted element).
  virtual double energy(const Eigen::Ref<const VecX>& x) const = 0;
  /// Adds dE/dx at x (N) to `gradient` (same size as x).
  virtual void add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const = 0;
  /// energy(x) (J, returned) and add_gradient(x, gradient) (N) together: blocks override it with one pass over
  /// their elements (the real-time integrators evaluate both at every trial point). Default: the two calls.
  virtual double energy_and_add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
    const double e = energy(x);
    add_gradient(x, gradient);
    return e;
  }
  /// #elements x nodes-per-element node indices of the elements whose Hessians the block adds (0 x 0 when its
  /// Hessian is zero). Fixes the sparsity pattern.
  virtual RowMatXi element_nodes() const = 0;
  /// Adds d2E/dx2 at x (N/m) into `values`, the value array of a matrix whose pattern contains the elements'
  /// node pairs, at the places `scatter` (built from element_nodes()) gives.
  /// @param project_psd  project each element's Hessian to positive semi-definite first
  virtual void add_hessian_values(const Eigen::Ref<const VecX>& x, const HessianScatter& scatter, double* values,
                                  bool project_psd) const = 0;

  /// True when the block's forces depend on where an interaction pushes (default false); Model then calls the
  /// interaction_ variants below when the problem has an interaction.
  virtual bool follows_interaction() const { return false; }
  /// add_gradient under `interaction` (default: add_gradient, the interaction ignored).
  virtual void add_interaction_gradient(const Eigen::Ref<const VecX>& x, const Interaction& interaction,
                                        Eigen::Ref<VecX> gradient) const {
    (void)interaction;
    add_gradient(x, gradient);
  }
  /// add_hessian_values under `interaction` (default: add_hessian_values, the interaction ignored).
  virtual void add_interaction_hessian_values(const Eigen::Ref<const VecX>& x, const Interaction& interaction,
                                              const HessianScatter& scatter, double* values, bool project_psd) const {
    (void)interaction;
    add_hessian_values(x, scatter, values, project_psd);
  }
};

}  // namespace hooke::model
