// Model::energy_and_gradient, the one pass per block the real-time integrators use, against the separate energy
// and gradient calls: on a benchmark model large enough for the parallel element schedule, and under an
// interaction (a block that follows one takes its interaction gradient).
#include <gtest/gtest.h>

#include <hooke/calibrate/model_factory.hpp>
#include <hooke/experiments/dynamics_benchmark.hpp>
#include <hooke/mesh/closed_surface.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/model.hpp>
#include <hooke/surface/discretisation.hpp>
#include <hooke/surface/volume_penalty_block.hpp>

namespace hooke::model {
namespace {

// A deformed configuration: rest positions times a smooth non-uniform factor.
VecX deformed(const VecX& rest) {
  VecX x = rest;
  for (Eigen::Index i = 0; i < x.size(); ++i) x(i) *= 0.98 + 0.02 * std::sin(0.37 * static_cast<double>(i));
  return x;
}

void expect_one_pass_matches(const Model& m, const VecX& x, const Interaction* interaction) {
  VecX g = VecX::Constant(x.size(), 7.0);  // overwritten, not added to
  const double e = m.energy_and_gradient(x, g, interaction);
  const double e_ref = m.energy(x);
  const VecX g_ref = m.gradient(x, interaction);
  EXPECT_NEAR(e, e_ref, 1e-13 * std::abs(e_ref));
  EXPECT_LT((g - g_ref).norm(), 1e-12 * g_ref.norm());
}

TEST(Model, EnergyAndGradientInOnePassMatchTheSeparateCalls) {
  const calibrate::CalibratedModel cm = experiments::benchmark_model(0, "any-nu-tet", 0.45);
  const calibrate::BuiltModel built = calibrate::build_model(cm);
  ASSERT_GE(cm.springs.pairs.size(), 4096u);  // the springs' schedule runs chunks in parallel
  const VecX x = deformed(built.model->rest_positions());
  EXPECT_GT(built.model->energy(x), 0.0);
  expect_one_pass_matches(*built.model, x, nullptr);
}

TEST(Model, EnergyAndGradientInOnePassFollowTheInteraction) {
  mesh::Mesh sphere = mesh::uv_sphere_surface(6, 8, 0.05);
  mesh::check_closed_surface(sphere);
  const surface::Discretisation d = surface::discretise(sphere, mesh::volume_centroid(sphere));
  const VecX rest = Eigen::Map<const VecX>(sphere.nodes.data(), sphere.nodes.size());
  Model m(3, rest);
  const double bulk = 5000.0;
  m.add(std::make_unique<surface::VolumePenaltyBlock>(sphere.elements, d.volume,
                                                      bulk * d.normal_volume.cwiseQuotient(d.normal_length.cwiseAbs2()),
                                                      d.normal_length, bulk, surface::VolumeForce::kNodal));
  const Interaction push{Vec3(0, 0, 0.05), Vec3(0, 0, -1), 0.06};
  const VecX x = rest * 0.99;
  expect_one_pass_matches(m, x, &push);
  expect_one_pass_matches(m, x, nullptr);
  VecX with(x.size()), without(x.size());
  m.energy_and_gradient(x, with, &push);
  m.energy_and_gradient(x, without, nullptr);
  EXPECT_GT((with - without).norm(), 0.0);
}

}  // namespace
}  // namespace hooke::model
