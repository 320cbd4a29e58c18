// The volume penalty (Arnab & Raja Eq. 3) and the weighted constraints (Eq. 4): the energy reading is the
// gradient of K/(2 V0) (V - V0)^2, the nodal reading the bulk pressure on each node's area, the weights sum
// to the node count and follow the interaction.
#include <gtest/gtest.h>

#include <hooke/mesh/closed_surface.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/surface/discretisation.hpp>
#include <hooke/surface/volume_penalty_block.hpp>
#include <support/block_checks.hpp>

namespace hooke::surface {
namespace {

struct Sphere {
  mesh::Mesh mesh = mesh::uv_sphere_surface(6, 8, 0.05);
  Discretisation d;
  VecX rest;
  Sphere() {
    mesh::check_closed_surface(mesh);
    d = discretise(mesh, mesh::volume_centroid(mesh));
    rest = Eigen::Map<const VecX>(mesh.nodes.data(), mesh.nodes.size());
  }
  VolumePenaltyBlock block(VolumeForce f, double bulk = 5000.0) const {
    return VolumePenaltyBlock(mesh.elements, d.volume,
                              bulk * d.normal_volume.cwiseQuotient(d.normal_length.cwiseAbs2()), d.normal_length, bulk,
                              f);
  }
  VecX deformed() const {
    VecX x = rest;
    for (Eigen::Index i = 0; i < x.size(); ++i) x(i) *= 0.97 + 0.01 * std::sin(3.0 * static_cast<double>(i));
    return x;
  }
};

TEST(VolumePenalty, EnergyReadingIsTheGradientOfTheBulkEnergy) {
  const Sphere s;
  const VolumePenaltyBlock b = s.block(VolumeForce::kEnergy);
  EXPECT_TRUE(b.conservative());
  const VecX x = s.deformed();
  const VecX g = test::block_gradient(b, x);
  const VecX g_fd = test::fd_gradient([&](const VecX& y) { return b.energy(y); }, x, 1e-7);
  EXPECT_LT((g - g_fd).norm(), 1e-6 * g.norm());
  // Its Hessian: the exact one minus the dropped off-diagonal node blocks of (K/V0) g g^T.
  const MatX h_fd = test::fd_jacobian([&](const VecX& y) { return test::block_gradient(b, y); }, x, 1e-7);
  VecX dv = VecX::Zero(x.size());  // dV/dx = -g V0 / (K (V0 - V))
  const double v = mesh::enclosed_volume(s.mesh.elements, x);
  dv = g * s.d.volume / (5000.0 * (v - s.d.volume));
  MatX dropped = (5000.0 / s.d.volume) * dv * dv.transpose();
  for (Eigen::Index i = 0; i < x.size() / 3; ++i) dropped.block(3 * i, 3 * i, 3, 3).setZero();
  EXPECT_LT((test::block_hessian(b, 3, x) + dropped - h_fd).norm(), 1e-6 * h_fd.norm());
  test::expect_fused_energy_and_gradient(b, x);
}

TEST(VolumePenalty, NodalReadingIsTheBulkPressureOnEachNodesArea) {
  const Sphere s;
  const VolumePenaltyBlock nodal = s.block(VolumeForce::kNodal), energy = s.block(VolumeForce::kEnergy);
  EXPECT_FALSE(nodal.conservative());
  VecX x = s.rest * 0.99;  // uniformly shrunk: V = 0.99^3 V0
  const VecX gn = test::block_gradient(nodal, x), ge = test::block_gradient(energy, x);
  // Both push out; per node they agree to the curvature of the neighbourhood (V_t = A_t L'/3 on flat ones).
  const double lost = 1.0 - 0.99 * 0.99 * 0.99;
  for (Eigen::Index i = 0; i < x.size() / 3; ++i) {
    const Vec3 n = s.d.normals.row(i).transpose();
    EXPECT_LT(gn.segment<3>(3 * i).dot(n), 0.0);
    EXPECT_NEAR(gn.segment<3>(3 * i).norm() / ge.segment<3>(3 * i).norm(), 1.0, 0.25) << "node " << i;
  }
  EXPECT_NEAR(gn.norm() / (5000.0 * lost), ge.norm() / (5000.0 * lost), 0.1 * ge.norm() / (5000.0 * lost));
  // At rest: no force.
  EXPECT_LT(test::block_gradient(nodal, s.rest).norm(), 1e-12);
}

TEST(VolumePenalty, WeightsSumToTheNodeCountAndFollowTheInteraction) {
  const Sphere s;
  const Interaction push{Vec3(0, 0, 0.05), Vec3(0, 0, -1), 0.06};
  const VecX w = interaction_weights(s.rest, push);
  EXPECT_NEAR(w.sum(), static_cast<double>(s.mesh.node_count()), 1e-10);
  EXPECT_GE(w.minCoeff(), 0.0);
  EXPECT_EQ(w(0), 0.0);  // the interaction point itself
  // Nodes beyond the radius or behind the push get nothing; among equal distances, the one more along the push
  // more.
  for (int i = 0; i < s.mesh.node_count(); ++i)
    if ((s.mesh.nodes.row(i).transpose() - push.point).norm() >= push.radius) {
      EXPECT_EQ(w(i), 0.0);
    }
  // Without an interaction, w = 1.
  const VolumePenaltyBlock b = s.block(VolumeForce::kNodal);
  EXPECT_EQ(b.weights(s.rest), VecX::Ones(s.mesh.node_count()));
  EXPECT_NEAR(b.weights(s.rest, &push).sum(), static_cast<double>(s.mesh.node_count()), 1e-10);
  // Under the interaction the penalty pushes nodes away from the interaction point.
  const VecX x = s.rest * 0.99;
  VecX g = VecX::Zero(x.size());
  b.add_interaction_gradient(x, push, g);
  for (int i = 1; i < s.mesh.node_count(); ++i)
    if (b.weights(x, &push)(i) > 0.0) {
      EXPECT_LT(g.segment<3>(3 * i).dot(x.segment<3>(3 * i) - push.point), 0.0);
    }
  // The block holds no interaction: its plain forces are those of w = 1 along the normals, as before.
  EXPECT_EQ(test::block_gradient(b, x), test::block_gradient(s.block(VolumeForce::kNodal), x));
  EXPECT_GT((test::block_gradient(b, x) - g).norm(), 0.0);
}

}  // namespace
}  // namespace hooke::surface
