#include <hooke/core/error.hpp>
#include <hooke/model/problem.hpp>

namespace hooke::model {

Problem make_problem(std::shared_ptr<const Model> model) {
  if (!model) throw InvalidArgument("make_problem: no model");
  Problem p;
  const int n = model->dof_count();
  p.fixed_dofs.assign(static_cast<size_t>(n), 0);
  p.external_force = VecX::Zero(n);
  p.model = std::move(model);
  return p;
}

void fix_nodes(Problem& problem, const std::vector<int>& nodes) {
  const int d = problem.model->dim();
  for (int node : nodes) {
    if (node < 0 || node >= problem.model->node_count())
      throw InvalidArgument("fix_nodes: node " + std::to_string(node) + " out of range");
    for (int c = 0; c < d; ++c) problem.fixed_dofs[static_cast<size_t>(d * node + c)] = 1;
  }
}

void zero_fixed_forces(const std::vector<char>& fixed_dofs, VecX& force) {
  if (static_cast<Eigen::Index>(fixed_dofs.size()) != force.size())
    throw InvalidArgument("zero_fixed_forces: " + std::to_string(fixed_dofs.size()) + " DOF flags for " +
                          std::to_string(force.size()) + " forces");
  for (std::size_t k = 0; k < fixed_dofs.size(); ++k)
    if (fixed_dofs[k]) force(static_cast<Eigen::Index>(k)) = 0.0;
}

std::vector<int> free_dofs(const Problem& problem) {
  const Model& m = *problem.model;
  const SparseMatrix k = m.hessian(m.rest_positions());
  const VecX diag = k.diagonal();
  std::vector<int> free;
  for (int i = 0; i < m.dof_count(); ++i)
    if (!problem.fixed_dofs[static_cast<size_t>(i)] && diag(i) != 0.0) free.push_back(i);
  return free;
}

VecX initial_positions(const Problem& problem) {
  VecX x = problem.model->rest_positions();
  if (problem.prescribed_positions.size() == x.size())
    for (Eigen::Index i = 0; i < x.size(); ++i)
      if (problem.fixed_dofs[static_cast<size_t>(i)]) x(i) = problem.prescribed_positions(i);
  return x;
}

double potential_energy(const Problem& problem, const Eigen::Ref<const VecX>& x, double load_factor) {
  return potential_energy(problem, x, problem.external_force, load_factor);
}

double potential_energy(const Problem& problem, const Eigen::Ref<const VecX>& x, const VecX& force,
                        double load_factor) {
  return problem.model->energy(x) - load_factor * force.dot(x - problem.model->rest_positions());
}

}  // namespace hooke::model
