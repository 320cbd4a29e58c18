#pragma once
// Dimension- and element-generic hyperelastic kernel: energy, gradient and Hessian of one element from its
// quadrature data (weights and reference shape-function gradients).
#include <hooke/material/detail/energy_density_impl.hpp>

namespace hooke::fem::detail {

template <int D, int N>
using Positions = Eigen::Matrix<double, N, D>;  // current node positions, row a = node a
template <int D, int N>
using Gradients = Eigen::Matrix<double, N, D>;  // dN_a/dX in row a
template <int D, int N>
using ElementVector = Eigen::Matrix<double, D * N, 1>;
template <int D, int N>
using ElementMatrix = Eigen::Matrix<double, D * N, D * N>;

template <int D, int N>
Eigen::Matrix<double, D, D> deformation_gradient(const Positions<D, N>& x, const Gradients<D, N>& dn) {
  return x.transpose() * dn;  // F_ij = sum_a x_ai dN_a/dX_j
}

// Adds w * [psi, dpsi/dx, d2psi/dx2] of one quadrature point. Returns false where psi is infinite.
template <int D, int N>
bool add_quadrature_point(material::Law law, const material::Lame& lame, double w, const Positions<D, N>& x,
                          const Gradients<D, N>& dn, double* energy, ElementVector<D, N>* gradient,
                          ElementMatrix<D, N>* hessian) {
  const Eigen::Matrix<double, D, D> f = deformation_gradient<D, N>(x, dn);
  if (energy) {
    // An inverted element (det F <= 0) is outside the domain of every law: StVK would otherwise admit the
    // mirrored, "stable" state a body reaches by collapsing through itself under compression.
    if (!(f.determinant() > 0.0)) return false;
    const double psi = material::detail::psi<D>(law, f, lame);
    if (!std::isfinite(psi)) return false;
    *energy += w * psi;
  }
  if (gradient) {
    const Eigen::Matrix<double, D, D> p = material::detail::piola<D>(law, f, lame);
    const Eigen::Matrix<double, N, D> g = dn * p.transpose();  // row a: P dN_a
    for (int a = 0; a < N; ++a)
      for (int i = 0; i < D; ++i) (*gradient)(D * a + i) += w * g(a, i);
  }
  if (hessian) {
    const auto dpdf = material::detail::piola_derivative<D>(law, f, lame);
    // d2psi/dx_ai dx_bk = sum_jl dP_ij/dF_kl dN_a,j dN_b,l with vec index i + D j.
    for (int a = 0; a < N; ++a)
      for (int b = 0; b < N; ++b)
        for (int i = 0; i < D; ++i)
          for (int k = 0; k < D; ++k) {
            double s = 0.0;
            for (int j = 0; j < D; ++j)
              for (int l = 0; l < D; ++l) s += dpdf(i + D * j, k + D * l) * dn(a, j) * dn(b, l);
            (*hessian)(D * a + i, D * b + k) += w * s;
          }
  }
  return true;
}

}  // namespace hooke::fem::detail
