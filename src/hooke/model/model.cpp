#include <cmath>
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

void Model::end_step(const Eigen::Ref<const VecX>& x) const {
  for (const auto& b : m_blocks) b->end_step(x);
}

bool Model::node_stiffness(const Eigen::Ref<const VecX>& x, std::vector<std::pair<int, Mat3>>& out) const {
  out.clear();
  bool any = false;
  for (const auto& b : m_blocks) any = b->add_node_stiffness(x, out) || any;
  return any;
}

double Model::energy(const Eigen::Ref<const VecX>& x) const {
  double e = 0.0;
  for (const auto& b : m_blocks) e += b->energy(x);
  return e;
}

VecX Model::gradient(const Eigen::Ref<const VecX>& x, const Interaction* interaction) const {
  VecX g(x.size());
  gradient(x, g, interaction);
  return g;
}

void Model::gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient, const Interaction* interaction) const {
  gradient.setZero();
  for (const auto& b : m_blocks)
    if (interaction && b->follows_interaction())
      b->add_interaction_gradient(x, *interaction, gradient);
    else
      b->add_gradient(x, gradient);
}

double Model::energy_and_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient,
                                  const Interaction* interaction) const {
  gradient.setZero();
  double e = 0.0;
  for (const auto& b : m_blocks)
    if (interaction && b->follows_interaction()) {
      e += b->energy(x);
      b->add_interaction_gradient(x, *interaction, gradient);
    } else {
      e += b->energy_and_add_gradient(x, gradient);
    }
  return e;
}

SparseMatrix Model::hessian(const Eigen::Ref<const VecX>& x, bool project_psd, const Interaction* interaction) const {
  HessianAssembly assembly(*this);
  assembly.assemble(x, project_psd, interaction);
  return assembly.matrix();
}

void require_valid(const Interaction& interaction) {
  if (!(interaction.radius > 0.0) || !std::isfinite(interaction.radius) || !(interaction.direction.norm() > 0.0) ||
      !interaction.direction.allFinite() || !interaction.point.allFinite())
    throw InvalidArgument("an interaction needs a finite point, a radius of influence > 0 and a non-zero direction");
}

}  // namespace hooke::model
