#include "colour_field.hpp"

#include <hooke/interactive/fields.hpp>

namespace hooke::viewer {

VecX ColourField::values(interactive::PhysicsLoop& loop, const interactive::Snapshot& snap, const VecX& rest, int dim,
                         const ViewState& state, double& lo, double& hi) {
  const int n = static_cast<int>(rest.size()) / dim;
  VecX value = VecX::Zero(n);
  lo = 0.0;
  hi = 1.0;
  switch (state.field) {
    case interactive::ColorField::kNone: break;
    case interactive::ColorField::kDisplacement:
      value = interactive::displacement_magnitude(snap.positions, rest, dim);
      hi = value.maxCoeff();
      break;
    case interactive::ColorField::kError:
      // Up to the largest error, but at least 1 % of the largest displacement: where the model is the FEM the map is
      // uniform (the lowest colour), not its round-off stretched over the whole range.
      if (state.ghost_positions && state.ghost_positions->size() == snap.positions.size())
        value = interactive::node_distance(snap.positions, *state.ghost_positions, dim);
      hi = std::max(value.maxCoeff(), 0.01 * interactive::displacement_magnitude(snap.positions, rest, dim).maxCoeff());
      break;
    case interactive::ColorField::kStrain:
      if (m_springs_version != snap.model_version) {  // the springs change only with the model
        loop.with([&](const interactive::LiveSimulation& sim) { m_springs = sim.model().springs; });
        m_springs_version = snap.model_version;
      }
      value = interactive::spring_strain(m_springs, snap.positions, n);
      hi = value.cwiseAbs().maxCoeff();
      lo = -hi;
      break;
    case interactive::ColorField::kYoung:  // the tissues of a model with regions, by stiffness
      if (m_young_version != snap.model_version) {
        loop.with(
            [&](const interactive::LiveSimulation& sim) { m_young = interactive::node_youngs_modulus(sim.model()); });
        m_young_version = snap.model_version;
      }
      value = m_young;
      lo = value.minCoeff();
      hi = value.maxCoeff();
      break;
    case interactive::ColorField::kWeights:
      // The blocks are shared and immutable: the weights are computed here, not under the physics' lock.
      if (m_built_version != snap.model_version) {
        loop.with([&](const interactive::LiveSimulation& sim) { m_built = sim.built_model(); });
        m_built_version = snap.model_version;
      }
      if (m_built.volume_penalty)
        value = m_built.volume_penalty->weights(snap.positions, snap.interaction ? &*snap.interaction : nullptr);
      else
        value.setOnes();
      break;
  }
  return value;
}

std::vector<std::array<float, 3>> ColourField::colours(interactive::PhysicsLoop& loop,
                                                       const interactive::Snapshot& snap, const VecX& rest, int dim,
                                                       ViewState& state) {
  double lo = 0.0, hi = 1.0;
  const VecX value = values(loop, snap, rest, dim, state, lo, hi);
  if (!(hi > lo)) hi = lo + 1e-12;
  state.colour_lo = lo;
  state.colour_hi = hi;
  std::vector<std::array<float, 3>> out(static_cast<size_t>(value.size()));
  for (Eigen::Index i = 0; i < value.size(); ++i)
    out[static_cast<size_t>(i)] = state.field == interactive::ColorField::kNone
                                      ? std::array<float, 3>{0.80f, 0.62f, 0.55f}
                                      : interactive::colormap((value(i) - lo) / (hi - lo));
  return out;
}

}  // namespace hooke::viewer
