#pragma once
// Central finite differences, the independent check of every gradient and Hessian (docs/architecture.md, independent
// checks).
#include <functional>
#include <hooke/core/types.hpp>

namespace hooke::test {

// Gradient of f at x by central differences with step h (relative to max(1, |x_i|) when relative).
inline VecX fd_gradient(const std::function<double(const VecX&)>& f, const VecX& x, double h) {
  VecX g(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    VecX xp = x, xm = x;
    xp(i) += h;
    xm(i) -= h;
    g(i) = (f(xp) - f(xm)) / (2.0 * h);
  }
  return g;
}

// Jacobian of a vector function g at x by central differences (column i = dg/dx_i).
inline MatX fd_jacobian(const std::function<VecX(const VecX&)>& g, const VecX& x, double h) {
  const VecX g0 = g(x);
  MatX j(g0.size(), x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    VecX xp = x, xm = x;
    xp(i) += h;
    xm(i) -= h;
    j.col(i) = (g(xp) - g(xm)) / (2.0 * h);
  }
  return j;
}

}  // namespace hooke::test
