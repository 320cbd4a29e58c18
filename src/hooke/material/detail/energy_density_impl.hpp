#pragma once
// Dimension-generic kernels behind energy_density.hpp.
#include <Eigen/Dense>
#include <cmath>
#include <hooke/material/material.hpp>
#include <limits>

namespace hooke::material::detail {

template <int D>
using MatD = Eigen::Matrix<double, D, D>;

template <int D>
double psi(Law law, const MatD<D>& f, const Lame& l) {
  const MatD<D> id = MatD<D>::Identity();
  switch (law) {
    case Law::kLinear: {
      const MatD<D> eps = 0.5 * (f + f.transpose()) - id;
      return l.mu * eps.squaredNorm() + 0.5 * l.lambda * eps.trace() * eps.trace();
    }
    case Law::kStVK: {
      const MatD<D> e = 0.5 * (f.transpose() * f - id);
      return l.mu * e.squaredNorm() + 0.5 * l.lambda * e.trace() * e.trace();
    }
    case Law::kNeoHookean: {
      const double j = f.determinant();
      if (!(j > 0.0)) return std::numeric_limits<double>::infinity();
      const double log_j = std::log(j);
      return 0.5 * l.mu * (f.squaredNorm() - D) - l.mu * log_j + 0.5 * l.lambda * log_j * log_j;
    }
  }
  return 0.0;
}

// Directional derivative of P at F in direction dF: dP = (dP/dF) : dF.
template <int D>
MatD<D> piola_differential(Law law, const MatD<D>& f, const MatD<D>& df, const Lame& l) {
  const MatD<D> id = MatD<D>::Identity();
  switch (law) {
    case Law::kLinear: return l.mu * (df + df.transpose()) + l.lambda * df.trace() * id;
    case Law::kStVK: {
      const MatD<D> e = 0.5 * (f.transpose() * f - id);
      const MatD<D> s = 2.0 * l.mu * e + l.lambda * e.trace() * id;
      const MatD<D> de = 0.5 * (df.transpose() * f + f.transpose() * df);
      const MatD<D> ds = 2.0 * l.mu * de + l.lambda * de.trace() * id;
      return df * s + f * ds;
    }
    case Law::kNeoHookean: {
      const MatD<D> f_inv = f.inverse();
      const MatD<D> f_inv_t = f_inv.transpose();
      const double log_j = std::log(f.determinant());
      return l.mu * df + (l.mu - l.lambda * log_j) * f_inv_t * df.transpose() * f_inv_t +
             l.lambda * (f_inv * df).trace() * f_inv_t;
    }
  }
  return MatD<D>::Zero();
}

template <int D>
MatD<D> piola(Law law, const MatD<D>& f, const Lame& l) {
  const MatD<D> id = MatD<D>::Identity();
  switch (law) {
    case Law::kLinear: {
      const MatD<D> eps = 0.5 * (f + f.transpose()) - id;
      return 2.0 * l.mu * eps + l.lambda * eps.trace() * id;
    }
    case Law::kStVK: {
      const MatD<D> e = 0.5 * (f.transpose() * f - id);
      return f * (2.0 * l.mu * e + l.lambda * e.trace() * id);
    }
    case Law::kNeoHookean: {
      const MatD<D> f_inv_t = f.inverse().transpose();
      return l.mu * (f - f_inv_t) + l.lambda * std::log(f.determinant()) * f_inv_t;
    }
  }
  return MatD<D>::Zero();
}

template <int D>
Eigen::Matrix<double, D * D, D * D> piola_derivative(Law law, const MatD<D>& f, const Lame& l) {
  Eigen::Matrix<double, D * D, D * D> out;
  for (int col = 0; col < D * D; ++col) {
    MatD<D> df = MatD<D>::Zero();
    df.data()[col] = 1.0;  // column-major: data index k + D l is F_kl
    const MatD<D> dp = piola_differential<D>(law, f, df, l);
    out.col(col) = Eigen::Map<const Eigen::Matrix<double, D * D, 1>>(dp.data());
  }
  return out;
}

}  // namespace hooke::material::detail
