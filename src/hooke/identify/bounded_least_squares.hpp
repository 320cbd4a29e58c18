#pragma once
/// Sparse, matrix-free least squares with lower bounds: min 1/2 |A theta - b|^2 subject to theta >= lower. With
/// lower = 0 this is the non-negative least squares of Lloyd et al. 2007, Eq. 2 (no negative springs).
#include <hooke/core/types.hpp>

namespace hooke::identify {

/// A linear map A: R^cols -> R^rows known only by its products (the force matrix U(x) of Eq. 2 is never formed).
class LinearOperator {
 public:
  virtual ~LinearOperator() = default;
  virtual Eigen::Index rows() const = 0;
  virtual Eigen::Index cols() const = 0;
  /// y = A x (y is resized to rows()).
  virtual void apply(const VecX& x, VecX& y) const = 0;
  /// x = A^T y (x is resized to cols()).
  virtual void apply_transpose(const VecX& y, VecX& x) const = 0;
  /// |A e_j|^2 for every column j (cols()).
  virtual VecX squared_column_norms() const = 0;
};

struct BoundedLeastSquaresOptions {
  /// converged when the projected gradient's norm <= tolerance x |A^T b| (both in column-scaled variables),
  /// default 1e-9
  double tolerance = 1e-9;
  int max_iterations = 1000;   ///< outer iterations (a projected-gradient phase plus a subspace phase), default 1000
  int max_cg_iterations = 50;  ///< conjugate-gradient iterations per subspace phase, default 50
  int projected_gradient_steps = 5;  ///< projected-gradient steps per outer iteration at most, default 5
};

struct BoundedLeastSquaresReport {
  int iterations = 0;               ///< outer iterations
  long cg_iterations = 0;           ///< conjugate-gradient iterations in all
  long products = 0;                ///< products with A and A^T in all
  double residual = 0.0;            ///< |A theta - b| at the end
  double projected_gradient = 0.0;  ///< relative projected-gradient norm at the end (the convergence measure)
  int at_bound = 0;                 ///< variables at their lower bound at the end
  /// columns of A that are zero: such a variable keeps its start value (at least lower), or is max(lower, 0) without a
  /// start
  int unseen = 0;
  bool converged = false;
};

/// Solves min 1/2 |A theta - b|^2 s.t. theta >= lower (entries of lower may be -infinity) by gradient projection
/// with conjugate gradients on the face of the free variables (More & Toraldo 1991, "On the solution of large
/// quadratic programming problems with bound constraints", SIAM J. Optim. 1), in variables scaled to unit
/// columns. The minimiser is unique when A has full column rank on the free variables.
/// @param a       the operator (rows x cols)
/// @param b       right-hand side (rows), finite
/// @param lower   lower bound per variable (cols), -infinity allowed
/// @param start   initial guess (cols) or empty (then max(lower, 0))
/// @throws InvalidArgument on mismatched sizes or a non-finite b
VecX solve_bounded_least_squares(const LinearOperator& a, const VecX& b, const VecX& lower, const VecX& start = {},
                                 const BoundedLeastSquaresOptions& options = {},
                                 BoundedLeastSquaresReport* report = nullptr);

/// A dense matrix as a LinearOperator (tests, small problems).
class DenseOperator final : public LinearOperator {
 public:
  explicit DenseOperator(MatX matrix) : m_matrix(std::move(matrix)) {}
  Eigen::Index rows() const override { return m_matrix.rows(); }
  Eigen::Index cols() const override { return m_matrix.cols(); }
  void apply(const VecX& x, VecX& y) const override { y.noalias() = m_matrix * x; }
  void apply_transpose(const VecX& y, VecX& x) const override { x.noalias() = m_matrix.transpose() * y; }
  VecX squared_column_norms() const override { return m_matrix.colwise().squaredNorm().transpose(); }

 private:
  MatX m_matrix;
};

}  // namespace hooke::identify
