#include <hooke/core/error.hpp>
#include <hooke/model/hessian_assembly.hpp>
#include <hooke/model/model.hpp>

namespace hooke::model {

Model::Model(int dim, VecX rest_positions) : m_dim(dim), m_rest(std::move(rest_positions)) {
  if (dim != 2 && dim != 3) throw InvalidArgument("Model: dim must be 2 or 3");
  if (m_rest.size() % dim != 0) throw InvalidArgument("Model: rest positions are not a multiple of dim");
}

void Model::add(std::unique_ptr<TermBlock> block) { m_blocks.push_back(std::move(block)); }

bool Model::exact_hessian() const {
  for (const auto& b : m_blocks)
    if (!b->exact_hessian()) return false;
  return true;
}

bool Model::conservative() const {
  for (const auto& b : m_blocks)
    if (!b->conservative()) return false;
  return true;
}

double Model::energy(const Eigen::Ref<const VecX>& x) const {
  double e = 0.0;
  for (const auto& b : m_blocks) e += b->energy(x);
  return e;
}

VecX Model::gradient(const Eigen::Ref<const VecX>& x) const {
  VecX g(x.size());
  gradient(x, g);
  return g;
}

void Model::gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
  gradient.setZero();
  for (const auto& b : m_blocks) b->add_gradient(x, gradient);
}

SparseMatrix Model::hessian(const Eigen::Ref<const VecX>& x, bool project_psd) const {
  HessianAssembly assembly(*this);
  assembly.assemble(x, project_psd);
  return assembly.matrix();
}

}  // namespace hooke::model
