#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/sparse_cholesky.hpp>
#include <hooke/core/symmetric_eigen.hpp>
#include <hooke/solve/contact_stiffness.hpp>
#include <limits>
#include <numeric>
#include <string>

namespace hooke::solve {

MatX contact_stiffness(const SparseMatrix& k, const std::vector<char>& fixed, const VecX& positions, int dim,
                       const std::vector<int>& nodes, const ContactStiffnessOptions& options) {
  return contact_response(k, fixed, positions, dim, nodes, options).stiffness;
}

ContactResponse contact_response(const SparseMatrix& k, const std::vector<char>& fixed, const VecX& positions, int dim,
                                 const std::vector<int>& nodes, const ContactStiffnessOptions& options) {
  const Eigen::Index nd = k.rows();
  if (dim < 1 || k.cols() != nd || positions.size() != nd || static_cast<Eigen::Index>(fixed.size()) != nd ||
      nd % dim != 0)
    throw InvalidArgument("contact_stiffness: the stiffness, positions and fixed flags must have dof_count entries");
  if (nodes.empty()) throw InvalidArgument("contact_stiffness needs at least one held node");
  if (options.region_nodes < 1) throw InvalidArgument("contact_stiffness: the region needs at least one node");
  const int n = static_cast<int>(nd / dim);
  for (const int i : nodes) {
    if (i < 0 || i >= n) throw InvalidArgument("contact_stiffness: node " + std::to_string(i) + " is out of range");
    for (int a = 0; a < dim; ++a)
      if (fixed[static_cast<size_t>(dim * i + a)])
        throw InvalidArgument("contact_stiffness: node " + std::to_string(i) + " is fixed");
  }
  // The region: the held nodes and the nodes nearest them.
  std::vector<int> region;
  if (options.region_nodes >= n) {
    region.resize(static_cast<size_t>(n));
    std::iota(region.begin(), region.end(), 0);
  } else {
    VecX distance = VecX::Constant(n, std::numeric_limits<double>::infinity());
    for (const int h : nodes)
      for (int i = 0; i < n; ++i)
        distance(i) = std::min(distance(i), (positions.segment(dim * i, dim) - positions.segment(dim * h, dim)).norm());
    region.resize(static_cast<size_t>(n));
    std::iota(region.begin(), region.end(), 0);
    const auto keep = std::max<size_t>(static_cast<size_t>(options.region_nodes), nodes.size());
    std::nth_element(region.begin(), region.begin() + static_cast<long>(keep) - 1, region.end(),
                     [&](int a, int b) { return distance(a) < distance(b) || (distance(a) == distance(b) && a < b); });
    region.resize(keep);
    std::sort(region.begin(), region.end());
  }
  std::vector<int> local(static_cast<size_t>(n), -1);  // node -> index in the region
  for (size_t r = 0; r < region.size(); ++r) local[static_cast<size_t>(region[r])] = static_cast<int>(r);
  // Held in the condensation: the fixed DOFs and the region's boundary (nodes coupled to a node outside it).
  const Eigen::Index m = dim * static_cast<Eigen::Index>(region.size());
  std::vector<char> held(static_cast<size_t>(m), 0);
  for (size_t r = 0; r < region.size(); ++r)
    for (int a = 0; a < dim; ++a) {
      const Eigen::Index c = dim * region[r] + a;
      bool boundary = fixed[static_cast<size_t>(c)] != 0;
      for (SparseMatrix::InnerIterator it(k, c); it && !boundary; ++it)
        boundary = it.value() != 0.0 && local[static_cast<size_t>(it.row() / dim)] < 0;
      if (boundary)
        for (int b = 0; b < dim; ++b) held[static_cast<size_t>(dim * static_cast<Eigen::Index>(r) + b)] = 1;
    }
  for (const int h : nodes)
    for (int a = 0; a < dim; ++a)
      if (held[static_cast<size_t>(dim * local[static_cast<size_t>(h)] + a)])
        throw InvalidArgument("contact_stiffness: held node " + std::to_string(h) +
                              " is on the region's boundary: make the region larger");
  // The probe moves every held node by the same offset, so dim solves give K_c (not one per held DOF): for a unit
  // offset along axis a, the region's free DOFs relax to u = -K_ff^-1 K_fh P e_a, and the probe's force is
  // column a of K_c = P^T (K_hh P e_a + K_hf u), the Schur complement's definition applied to P e_a.
  std::vector<char> probe(static_cast<size_t>(m), 0);
  for (const int h : nodes)
    for (int a = 0; a < dim; ++a) probe[static_cast<size_t>(dim * local[static_cast<size_t>(h)] + a)] = 1;
  const auto local_dof = [&](Eigen::Index global) {  // -1 outside the region
    const int node = local[static_cast<size_t>(global / dim)];
    return node < 0 ? Eigen::Index{-1} : dim * static_cast<Eigen::Index>(node) + global % dim;
  };
  // K_ff on the region, the held and probe DOFs' rows and columns those of the identity.
  std::vector<Triplet> t;
  for (size_t r = 0; r < region.size(); ++r)
    for (int a = 0; a < dim; ++a) {
      const Eigen::Index c = dim * region[r] + a, lc = dim * static_cast<Eigen::Index>(r) + a;
      if (held[static_cast<size_t>(lc)] || probe[static_cast<size_t>(lc)]) {
        t.emplace_back(lc, lc, 1.0);
        continue;
      }
      for (SparseMatrix::InnerIterator it(k, c); it; ++it) {
        const Eigen::Index lr = local_dof(it.row());
        if (lr >= 0 && !held[static_cast<size_t>(lr)] && !probe[static_cast<size_t>(lr)])
          t.emplace_back(lr, lc, it.value());
      }
    }
  SparseMatrix kff(m, m);
  kff.setFromTriplets(t.begin(), t.end());
  SparseCholesky factor;
  if (!factor.factorize(kff))
    throw SolverFailure(
        "contact_stiffness: the stiffness of the region around the held nodes is not positive "
        "definite (is the body held?)");
  MatX kc(dim, dim), diagonal = MatX::Zero(dim, dim), modes = MatX::Zero(nd, dim);
  VecX u(m);
  for (int a = 0; a < dim; ++a) {
    u.setZero();
    for (const int h : nodes)  // -K_fh P e_a
      for (SparseMatrix::InnerIterator it(k, dim * static_cast<Eigen::Index>(h) + a); it; ++it) {
        const Eigen::Index lr = local_dof(it.row());
        if (lr >= 0 && !held[static_cast<size_t>(lr)] && !probe[static_cast<size_t>(lr)]) u(lr) -= it.value();
      }
    factor.solve_in_place(u.data(), 1);
    for (const int h : nodes) u(dim * local[static_cast<size_t>(h)] + a) = 1.0;
    for (size_t r = 0; r < region.size(); ++r)
      for (int b = 0; b < dim; ++b) {
        const Eigen::Index lr = dim * static_cast<Eigen::Index>(r) + b;
        if (!held[static_cast<size_t>(lr)]) modes(dim * region[r] + b, a) = u(lr);
      }
    for (int b = 0; b < dim; ++b) {
      double f = 0.0;
      for (const int h : nodes)  // symmetric k: row (h, b) read as its column
        for (SparseMatrix::InnerIterator it(k, dim * static_cast<Eigen::Index>(h) + b); it; ++it) {
          const Eigen::Index lr = local_dof(it.row());
          if (lr < 0) continue;
          f += it.value() * u(lr);
          if (probe[static_cast<size_t>(lr)] && lr % dim == a) diagonal(b, a) += it.value();
        }
      kc(b, a) = f;
    }
  }
  kc = 0.5 * (kc + kc.transpose()).eval();
  // A body held by the probe alone follows it rigidly: K_c is singular against the held nodes' own stiffness.
  const double own = (0.5 * (diagonal + diagonal.transpose())).norm();
  if (!(symmetric_eigenvalues(kc)(0) > 1e-9 * own))
    throw SolverFailure("contact_stiffness: the held nodes' stiffness is singular (is the body held?)");
  return {kc, modes};
}

MatX contact_curvature(const model::Model& model, const VecX& positions, const MatX& modes, double step,
                       const model::Interaction* interaction) {
  const int dim = static_cast<int>(modes.cols());
  if (dim < 1 || modes.rows() != model.dof_count() || positions.size() != model.dof_count())
    throw InvalidArgument("contact_curvature: the positions and modes must have dof_count rows");
  if (!(step > 0.0) || !std::isfinite(step)) throw InvalidArgument("contact_curvature: the step must be > 0 m");
  const double largest = modes.cwiseAbs().maxCoeff();
  if (!(largest > 0.0)) throw InvalidArgument("contact_curvature: the modes are zero");
  // h X moves no node by more than `step` (2 h along a doubled mode: h = step / (2 largest)).
  const double h = step / (2.0 * largest);
  VecX g(model.dof_count()), sum(model.dof_count());
  const auto gradient_at = [&](const VecX& direction, double sign) -> const VecX& {
    model.gradient(positions + sign * h * direction, g, interaction);
    if (!g.allFinite())
      throw SolverFailure("contact_curvature: the gradient is not finite " + std::to_string(step) +
                          " m from the state (an element inverts: use a smaller step)");
    return g;
  };
  // Second directional difference of the gradient: D^2 G [X_a, X_b] = (G(+p) + G(-p) - G(+q) - G(-q)) / (4 h^2)
  // with p = X_a + X_b, q = X_a - X_b (polarisation; q = 0 when a = b); error O(h^2).
  MatX t(dim, dim * dim);
  for (int a = 0; a < dim; ++a)
    for (int b = a; b < dim; ++b) {
      const VecX p = modes.col(a) + modes.col(b), q = modes.col(a) - modes.col(b);
      sum = gradient_at(p, 1.0);
      sum += gradient_at(p, -1.0);
      sum -= gradient_at(q, 1.0);
      sum -= gradient_at(q, -1.0);
      sum /= 4.0 * h * h;
      for (int c = 0; c < dim; ++c) t(c, a * dim + b) = t(c, b * dim + a) = modes.col(c).dot(sum);
    }
  return t;
}

}  // namespace hooke::solve
