#include <hooke/core/error.hpp>
#include <hooke/solve/node_compliance.hpp>
#include <string>

namespace hooke::solve {

NodeCompliance::NodeCompliance(const SparseMatrix& k, const std::vector<char>& fixed, int dim)
    : m_dim(dim), m_dofs(k.rows()), m_fixed(fixed) {
  if (dim < 1 || dim > 3 || k.cols() != m_dofs || static_cast<Eigen::Index>(fixed.size()) != m_dofs ||
      m_dofs % dim != 0)
    throw InvalidArgument("node compliance: the stiffness and the fixed flags must have dof_count entries");
  // K_ff with the fixed DOFs' rows and columns those of the identity (their columns of the inverse are then unit
  // vectors, dropped below).
  std::vector<Triplet> t;
  t.reserve(static_cast<size_t>(k.nonZeros()));
  for (Eigen::Index c = 0; c < m_dofs; ++c) {
    if (fixed[static_cast<size_t>(c)]) {
      t.emplace_back(c, c, 1.0);
      continue;
    }
    for (SparseMatrix::InnerIterator it(k, c); it; ++it)
      if (!fixed[static_cast<size_t>(it.row())]) t.emplace_back(it.row(), c, it.value());
  }
  SparseMatrix kff(m_dofs, m_dofs);
  kff.setFromTriplets(t.begin(), t.end());
  if (!m_factor.factorize(kff))
    throw SolverFailure(
        "node compliance: the body's stiffness is not positive definite on its free DOFs (is it held?)");
}

const MatX& NodeCompliance::columns(int node) {
  if (const auto it = m_columns.find(node); it != m_columns.end()) return it->second;
  if (static_cast<int>(m_columns.size()) >= max_cached) m_columns.clear();
  // dim right-hand sides interleaved (SparseCholesky::solve_in_place): b[dim i + r].
  std::vector<double> b(static_cast<size_t>(m_dofs * m_dim), 0.0);
  for (int a = 0; a < m_dim; ++a) {
    const Eigen::Index dof = static_cast<Eigen::Index>(m_dim) * node + a;
    if (!m_fixed[static_cast<size_t>(dof)]) b[static_cast<size_t>(dof * m_dim + a)] = 1.0;
  }
  m_factor.solve_exact_in_place(b.data(), m_dim);
  MatX c(m_dofs, m_dim);
  for (Eigen::Index i = 0; i < m_dofs; ++i)
    for (int a = 0; a < m_dim; ++a)
      c(i, a) = m_fixed[static_cast<size_t>(i)] ? 0.0 : b[static_cast<size_t>(i * m_dim + a)];
  return m_columns.emplace(node, std::move(c)).first->second;
}

MatX NodeCompliance::block(const std::vector<int>& nodes) {
  const Eigen::Index n = static_cast<Eigen::Index>(m_dofs / m_dim);
  for (const int i : nodes)
    if (i < 0 || i >= n) throw InvalidArgument("node compliance: node " + std::to_string(i) + " is out of range");
  const auto k = static_cast<Eigen::Index>(nodes.size());
  MatX out(m_dim * k, m_dim * k);
  for (Eigen::Index q = 0; q < k; ++q) {
    const MatX& col = columns(nodes[static_cast<size_t>(q)]);
    for (Eigen::Index p = 0; p < k; ++p)
      out.block(m_dim * p, m_dim * q, m_dim, m_dim) = col.middleRows(m_dim * nodes[static_cast<size_t>(p)], m_dim);
  }
  return 0.5 * (out + out.transpose());
}

}  // namespace hooke::solve
