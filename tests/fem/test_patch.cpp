// Patch tests: a linear displacement field imposed on the boundary of an irregular mesh is reproduced
// exactly inside it, by CST, Q4 and tet4 (linear law) and by the nonlinear laws for a homogeneous F.
#include <gtest/gtest.h>

#include <hooke/fem/elastic_block.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/topology.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <random>
#include <set>
#include <support/meshes.hpp>

namespace hooke::fem {
namespace {

using material::Law;

struct PatchCase {
  mesh::ElementKind kind;
  Law law;
};

class PatchTest : public ::testing::TestWithParam<PatchCase> {};

TEST_P(PatchTest, LinearFieldReproducedExactly) {
  const mesh::Mesh m = test::irregular_mesh(GetParam().kind, 5, 0.3);
  const int d = m.dim();
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-0.08, 0.08);
  MatX f = MatX::Identity(d, d);
  for (Eigen::Index i = 0; i < f.size(); ++i) f.data()[i] += u(rng);
  VecX shift(d);
  for (int c = 0; c < d; ++c) shift(c) = 0.01 * u(rng);
  // Small enough that the linear law's "exact" field is the field itself; the nonlinear ones take any F.
  if (GetParam().law == Law::kLinear) f = MatX::Identity(d, d) + 0.01 * (f - MatX::Identity(d, d));

  auto model = std::make_shared<model::Model>(d, test::flat_positions(m));
  model->add(std::make_unique<ElasticBlock>(m, std::vector<material::Material>{{GetParam().law, 5000.0, 0.3}}));
  model::Problem p = model::make_problem(model);
  const RowMatXi facets = mesh::boundary_facets(m);
  std::set<int> boundary(facets.data(), facets.data() + facets.size());
  p.fixed_dofs.assign(static_cast<size_t>(model->dof_count()), 0);
  p.prescribed_positions = VecX::Zero(model->dof_count());
  VecX exact(model->dof_count());
  for (int i = 0; i < m.node_count(); ++i) {
    const VecX xi = f * m.nodes.row(i).transpose() + shift;
    exact.segment(d * i, d) = xi;
  }
  for (int i : boundary)
    for (int c = 0; c < d; ++c) {
      p.fixed_dofs[static_cast<size_t>(d * i + c)] = 1;
      p.prescribed_positions(d * i + c) = exact(d * i + c);
    }
  ASSERT_LT(boundary.size(), static_cast<size_t>(m.node_count())) << "the patch needs interior nodes";
  solve::StaticResult r = GetParam().law == Law::kLinear ? solve::linear_static(p) : solve::static_equilibrium(p);
  solve::require_converged(r.report);
  EXPECT_LT((r.positions - exact).cwiseAbs().maxCoeff(), 1e-10 * 0.05) << r.report.message;
}

INSTANTIATE_TEST_SUITE_P(Elements, PatchTest,
                         ::testing::Values(PatchCase{mesh::ElementKind::kTriangle, Law::kLinear},
                                           PatchCase{mesh::ElementKind::kQuad, Law::kLinear},
                                           PatchCase{mesh::ElementKind::kTet, Law::kLinear},
                                           PatchCase{mesh::ElementKind::kTriangle, Law::kStVK},
                                           PatchCase{mesh::ElementKind::kQuad, Law::kNeoHookean},
                                           PatchCase{mesh::ElementKind::kTet, Law::kStVK},
                                           PatchCase{mesh::ElementKind::kTet, Law::kNeoHookean}),
                         [](const auto& param_info) {
                           return std::string(mesh::element_kind_name(param_info.param.kind)) + "_" +
                                  std::string(material::law_name(param_info.param.law));
                         });

}  // namespace
}  // namespace hooke::fem
