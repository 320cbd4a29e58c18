#include <algorithm>
#include <hooke/core/error.hpp>
#include <hooke/core/sparse_cholesky.hpp>
#include <hooke/solve/contact_stiffness.hpp>
#include <limits>
#include <numeric>
#include <string>

namespace hooke::solve {

MatX contact_stiffness(const SparseMatrix& k, const std::vector<char>& fixed, const VecX& positions, int dim,
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
  // K_rr on the region, the held DOFs' rows and columns those of the identity.
  std::vector<Triplet> t;
  for (size_t r = 0; r < region.size(); ++r)
    for (int a = 0; a < dim; ++a) {
      const Eigen::Index c = dim * region[r] + a, lc = dim * static_cast<Eigen::Index>(r) + a;
      if (held[static_cast<size_t>(lc)]) {
        t.emplace_back(lc, lc, 1.0);
        continue;
      }
      for (SparseMatrix::InnerIterator it(k, c); it; ++it) {
        const int node = local[static_cast<size_t>(it.row() / dim)];
        if (node < 0) continue;
        const Eigen::Index lr = dim * static_cast<Eigen::Index>(node) + it.row() % dim;
        if (!held[static_cast<size_t>(lr)]) t.emplace_back(lr, lc, it.value());
      }
    }
  SparseMatrix krr(m, m);
  krr.setFromTriplets(t.begin(), t.end());
  SparseCholesky factor;
  if (!factor.factorize(krr))
    throw SolverFailure(
        "contact_stiffness: the stiffness of the region around the held nodes is not positive "
        "definite (is the body held?)");
  // C = E^T K_rr^-1 E over the held nodes' DOFs, then K_c = P^T C^-1 P.
  const Eigen::Index c = dim * static_cast<Eigen::Index>(nodes.size());
  MatX w = MatX::Zero(m, c);
  for (size_t h = 0; h < nodes.size(); ++h)
    for (int a = 0; a < dim; ++a)
      w(dim * local[static_cast<size_t>(nodes[h])] + a, dim * static_cast<Eigen::Index>(h) + a) = 1.0;
  for (Eigen::Index j = 0; j < c; ++j) factor.solve_in_place(w.col(j).data(), 1);
  MatX cap(c, c);
  for (size_t h = 0; h < nodes.size(); ++h)
    for (int a = 0; a < dim; ++a)
      cap.row(dim * static_cast<Eigen::Index>(h) + a) = w.row(dim * local[static_cast<size_t>(nodes[h])] + a);
  cap = 0.5 * (cap + cap.transpose()).eval();
  MatX p = MatX::Zero(c, dim);
  for (size_t h = 0; h < nodes.size(); ++h) p.block(dim * static_cast<Eigen::Index>(h), 0, dim, dim).setIdentity();
  const Eigen::LDLT<MatX> ldlt(cap);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 0.0))
    throw SolverFailure("contact_stiffness: the held nodes' compliance is singular (nodes repeated?)");
  MatX kc = p.transpose() * ldlt.solve(p);
  return 0.5 * (kc + kc.transpose());
}

}  // namespace hooke::solve
