#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/identify/bounded_least_squares.hpp>
#include <limits>

namespace hooke::identify {
namespace {

// A with unit columns: z = s .* theta, A-hat z = A (z ./ s). Zero columns ("unseen") get inv_scale 0 and are frozen.
class ScaledOperator {
 public:
  ScaledOperator(const LinearOperator& a, VecX inv_scale, long& products)
      : m_a(a), m_inv_scale(std::move(inv_scale)), m_products(products) {}
  void apply(const VecX& z, VecX& y) const {
    m_theta = z.cwiseProduct(m_inv_scale);
    m_a.apply(m_theta, y);
    ++m_products;
  }
  void apply_transpose(const VecX& r, VecX& g) const {
    m_a.apply_transpose(r, g);
    g.array() *= m_inv_scale.array();
    ++m_products;
  }

 private:
  const LinearOperator& m_a;
  VecX m_inv_scale;
  long& m_products;
  mutable VecX m_theta;
};

// The iterate and everything derived from it: residual r = A z - b, gradient g = A^T r, objective q = |r|^2 / 2.
struct Iterate {
  VecX z, r, g;
  double q = 0.0;
};

class Solver {
 public:
  Solver(const ScaledOperator& a, const VecX& b, VecX lower, std::vector<char> frozen)
      : m_a(a), m_b(b), m_lower(std::move(lower)), m_frozen(std::move(frozen)) {}

  void evaluate(Iterate& it) const {
    m_a.apply(it.z, it.r);
    it.r -= m_b;
    it.q = 0.5 * it.r.squaredNorm();
    m_a.apply_transpose(it.r, it.g);
  }

  bool at_bound(const Iterate& it, Eigen::Index j) const { return it.z(j) <= m_lower(j); }

  VecX projected_gradient(const Iterate& it) const {
    VecX pg = it.g;
    for (Eigen::Index j = 0; j < pg.size(); ++j)
      if (m_frozen[j] || (at_bound(it, j) && pg(j) > 0.0)) pg(j) = 0.0;
    return pg;
  }

  VecX project(VecX z) const {
    for (Eigen::Index j = 0; j < z.size(); ++j) z(j) = m_frozen[j] ? m_lower(j) : std::max(z(j), m_lower(j));
    return z;
  }

  // Armijo search along the projected path z(alpha) = P(z + alpha d), alpha = alpha0, alpha0/2, ... The change of q
  // is computed from w = A (z(alpha) - z) as r.w + w.w/2, not as a difference of q values, which drowns in
  // round-off near the minimum. Returns false when no decrease was found.
  bool projected_search(Iterate& it, const VecX& d, double alpha) const {
    VecX z, w;
    for (int halving = 0; halving < 40; ++halving, alpha *= 0.5) {
      z = project(it.z + alpha * d);
      const VecX step = z - it.z;
      const double predicted = it.g.dot(step);
      if (!(predicted < 0.0)) return false;
      m_a.apply(step, w);
      const double change = it.r.dot(w) + 0.5 * w.squaredNorm();
      if (change <= 1e-4 * predicted) {
        it.z = std::move(z);
        it.r += w;
        it.q += change;
        m_a.apply_transpose(it.r, it.g);
        return true;
      }
    }
    return false;
  }

  // Up to `steps` projected steepest-descent steps, stopped when the active set stops changing or the decrease
  // flattens (More & Toraldo's first phase). Returns false when no step made progress.
  bool gradient_projection(Iterate& it, int steps) const {
    bool moved = false;
    double best_decrease = 0.0;
    VecX w;
    for (int k = 0; k < steps; ++k) {
      const VecX pg = projected_gradient(it);
      m_a.apply(pg, w);
      const double curvature = w.squaredNorm();
      if (!(curvature > 0.0)) break;
      const std::vector<char> before = active_set(it);
      const double q_before = it.q;
      if (!projected_search(it, -it.g, pg.squaredNorm() / curvature)) break;
      moved = true;
      const double decrease = q_before - it.q;
      best_decrease = std::max(best_decrease, decrease);
      if (active_set(it) == before || decrease <= 0.1 * best_decrease) break;
    }
    return moved;
  }

  // Conjugate gradients on the normal equations restricted to the free face {z > lower}, to relative residual eta.
  VecX subspace_direction(const Iterate& it, double eta, int max_iterations, long& cg_iterations) const {
    const Eigen::Index n = it.z.size();
    VecX mask = VecX::Zero(n);
    for (Eigen::Index j = 0; j < n; ++j)
      if (!m_frozen[j] && !at_bound(it, j)) mask(j) = 1.0;
    VecX d = VecX::Zero(n), res = -it.g.cwiseProduct(mask), p = res, w, h;
    const double target = eta * res.norm();
    double rr = res.squaredNorm();
    for (int k = 0; k < max_iterations && std::sqrt(rr) > target; ++k) {
      m_a.apply(p, w);
      const double pap = w.squaredNorm();
      if (!(pap > 0.0)) break;
      const double alpha = rr / pap;
      d += alpha * p;
      m_a.apply_transpose(w, h);
      res -= alpha * h.cwiseProduct(mask);
      const double rr_next = res.squaredNorm();
      p = res + (rr_next / rr) * p;
      rr = rr_next;
      ++cg_iterations;
    }
    return d;
  }

  std::vector<char> active_set(const Iterate& it) const {
    std::vector<char> out(it.z.size());
    for (Eigen::Index j = 0; j < it.z.size(); ++j) out[j] = at_bound(it, j) ? 1 : 0;
    return out;
  }

 private:
  const ScaledOperator& m_a;
  const VecX& m_b;
  VecX m_lower;
  std::vector<char> m_frozen;
};

}  // namespace

VecX solve_bounded_least_squares(const LinearOperator& a, const VecX& b, const VecX& lower, const VecX& start,
                                 const BoundedLeastSquaresOptions& options, BoundedLeastSquaresReport* report) {
  const Eigen::Index n = a.cols();
  if (b.size() != a.rows() || lower.size() != n || (start.size() != 0 && start.size() != n))
    throw InvalidArgument("bounded least squares: b needs one entry per row, lower and start one per column");
  if (!b.allFinite()) throw InvalidArgument("bounded least squares: the right-hand side is not finite");
  BoundedLeastSquaresReport rep;
  const VecX norms = a.squared_column_norms().cwiseSqrt();
  VecX inv_scale = VecX::Zero(n), lower_z(n), theta0(n);
  std::vector<char> frozen(n, 0);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double start_j = start.size() ? start(j) : 0.0;
    theta0(j) = std::max(std::isfinite(start_j) ? start_j : 0.0, lower(j));
    if (norms(j) > 0.0 && std::isfinite(norms(j))) {
      inv_scale(j) = 1.0 / norms(j);
      lower_z(j) = lower(j) * norms(j);  // -inf stays -inf
    } else {
      frozen[j] = 1;
      ++rep.unseen;
      lower_z(j) = 0.0;
      if (!start.size()) theta0(j) = std::max(lower(j), 0.0);  // with a start it keeps its start value
    }
  }
  const ScaledOperator scaled(a, inv_scale, rep.products);
  const Solver solver(scaled, b, lower_z, frozen);
  Iterate it;
  it.z = solver.project(theta0.cwiseProduct(norms));
  solver.evaluate(it);
  VecX atb;
  scaled.apply_transpose(b, atb);
  const double scale = std::max(atb.norm(), std::numeric_limits<double>::min());
  for (rep.iterations = 0; rep.iterations < options.max_iterations; ++rep.iterations) {
    rep.projected_gradient = solver.projected_gradient(it).norm() / scale;
    if (rep.projected_gradient <= options.tolerance) {
      rep.converged = true;
      break;
    }
    if (rep.iterations > 0) solver.evaluate(it);  // the residual afresh, not accumulated steps
    const bool projected = solver.gradient_projection(it, options.projected_gradient_steps);
    const double pg = solver.projected_gradient(it).norm() / scale;
    const double eta = std::clamp(std::sqrt(pg), 0.1 * options.tolerance, 0.1);
    const VecX d = solver.subspace_direction(it, eta, options.max_cg_iterations, rep.cg_iterations);
    const bool searched = d.squaredNorm() > 0.0 && solver.projected_search(it, d, 1.0);
    if (!projected && !searched) break;  // no progress in either phase: round-off level
  }
  rep.projected_gradient = solver.projected_gradient(it).norm() / scale;
  rep.converged = rep.converged || rep.projected_gradient <= options.tolerance;
  rep.residual = it.r.norm();
  VecX theta(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    theta(j) = frozen[j] ? theta0(j) : it.z(j) * inv_scale(j);
    if (!frozen[j] && solver.at_bound(it, j)) {
      theta(j) = lower(j);
      ++rep.at_bound;
    }
  }
  if (report) *report = rep;
  return theta;
}

}  // namespace hooke::identify
