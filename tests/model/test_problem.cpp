// model::Problem helpers: supports and the forces on them.
#include <gtest/gtest.h>

#include <hooke/core/error.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/problem.hpp>

namespace hooke::model {
namespace {

// A support takes the load that acts on it: the forces on fixed DOFs are zeroed, the others kept.
TEST(Problem, ZeroFixedForcesClearsOnlyTheSupports) {
  const mesh::Mesh m = mesh::tet_box(0.01, 0.01, 0.01, 1, 1, 1);
  Problem p = make_problem(fem::linear_model(m, {{material::Law::kLinear, 1000.0, 0.3}}));
  p.external_force = VecX::LinSpaced(p.model->dof_count(), 1.0, static_cast<double>(p.model->dof_count()));
  const VecX before = p.external_force;
  fix_nodes(p, {0, 3});
  zero_fixed_forces(p);
  for (Eigen::Index k = 0; k < before.size(); ++k)
    EXPECT_EQ(p.external_force(k), p.fixed_dofs[static_cast<size_t>(k)] ? 0.0 : before(k)) << k;
  EXPECT_EQ(p.external_force.segment(0, 3).norm(), 0.0);
  VecX short_force = VecX::Ones(3);
  EXPECT_THROW(zero_fixed_forces(p.fixed_dofs, short_force), InvalidArgument);
}

}  // namespace
}  // namespace hooke::model
