// The condensed contact stiffness (multirate haptics' local model) against an independent derivation: the holding
// forces of the linear static equilibria (solve::linear_static, a direct solve on the free DOFs) with the held
// nodes displaced along each axis, divided by the displacement. A region smaller than the body holds more and is
// measured against it.
#include <gtest/gtest.h>

#include <hooke/calibrate/model_factory.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/symmetric_eigen.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/hessian_assembly.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/model/problem.hpp>
#include <hooke/solve/contact_stiffness.hpp>
#include <hooke/solve/node_compliance.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <iostream>

namespace hooke::solve {
namespace {

struct Body {
  calibrate::CalibratedModel model;
  calibrate::BuiltModel built;
  std::vector<int> clamped;
  std::vector<char> fixed;
  SparseMatrix k;
};

Body body(const std::string& method, int radial, int layers) {
  Body b;
  const mesh::Mesh m = mesh::tet_cylinder(0.01, 0.02, radial, layers);
  calibrate::ModelOptions o;
  o.method = method;
  b.model = calibrate::calibrate_model(m, {material::Law::kLinear, 14630.0, 0.45}, o);
  b.built = calibrate::build_model(b.model);
  b.clamped = model::make_load_case(m, model::LoadKind::kStretch, 0.0, 1.0).fixed_nodes;
  b.fixed.assign(static_cast<size_t>(3 * m.node_count()), 0);
  for (const int i : b.clamped)
    for (int a = 0; a < 3; ++a) b.fixed[static_cast<size_t>(3 * i + a)] = 1;
  model::HessianAssembly a(*b.built.model);
  a.assemble(b.built.model->rest_positions(), false);
  b.k = a.matrix();
  return b;
}

// The top nodes within `radius` of the axis (the one nearest it when none is).
std::vector<int> top_nodes(const mesh::Mesh& m, double radius) {
  const double top = m.nodes.col(2).maxCoeff();
  std::vector<int> out;
  int nearest = -1;
  for (int i = 0; i < m.node_count(); ++i) {
    if (m.nodes(i, 2) < top - 1e-9) continue;
    if (m.nodes.row(i).head(2).norm() <= radius) out.push_back(i);
    if (nearest < 0 || m.nodes.row(i).head(2).norm() < m.nodes.row(nearest).head(2).norm()) nearest = i;
  }
  if (out.empty()) out.push_back(nearest);
  return out;
}

// dim x dim: column a is the holding force when every held node is moved by delta along axis a, over delta.
MatX holding_stiffness(const Body& b, const std::vector<int>& held, double delta) {
  MatX out(3, 3);
  for (int a = 0; a < 3; ++a) {
    model::Problem p = model::make_problem(b.built.model);
    model::fix_nodes(p, b.clamped);
    model::fix_nodes(p, held);
    p.prescribed_positions = b.built.model->rest_positions();
    for (const int i : held) p.prescribed_positions(3 * i + a) += delta;
    const StaticResult r = linear_static(p);
    EXPECT_EQ(r.report.status, SolveStatus::kConverged) << r.report.message;
    // The force that holds them there, K u at their DOFs (the linearised force: the geometric nonlinearity of a
    // finite difference of the gradient would stand at delta / element size, 1e-3 here).
    const VecX g = b.k * (r.positions - b.built.model->rest_positions());
    Vec3 holding = Vec3::Zero();
    for (const int i : held) holding += g.segment<3>(3 * i);
    out.col(a) = holding / delta;
  }
  return out;
}

TEST(ContactStiffness, EqualsTheHoldingForcesOfDisplacedEquilibria) {
  for (const char* method : {"fem", "any-nu-tet"}) {
    const Body b = body(method, 6, 4);
    const mesh::Mesh& m = b.model.mesh;
    for (const double radius : {1e-9, 0.004}) {
      const std::vector<int> held = top_nodes(m, radius);
      ASSERT_FALSE(held.empty());
      const MatX kc = contact_stiffness(b.k, b.fixed, b.built.model->rest_positions(), 3, held);
      const MatX reference = holding_stiffness(b, held, 1e-6);
      EXPECT_LT((kc - reference).norm(), 1e-8 * reference.norm()) << method << ", " << held.size() << " held nodes:\n"
                                                                  << kc << "\nagainst\n"
                                                                  << reference;
      EXPECT_LT((kc - kc.transpose()).norm(), 1e-12 * kc.norm());
      EXPECT_GT(symmetric_eigenvalues(kc).minCoeff(), 0.0);
    }
  }
}

// A region smaller than the body holds its boundary, so it is stiffer (K_region - K_body positive semidefinite),
// and less so the larger it is.
TEST(ContactStiffness, ASmallerRegionIsStifferAndConvergesWithItsSize) {
  const Body b = body("any-nu-tet", 8, 8);
  const mesh::Mesh& m = b.model.mesh;
  const std::vector<int> held = top_nodes(m, 1e-9);
  const VecX& x = b.built.model->rest_positions();
  const MatX whole = contact_stiffness(b.k, b.fixed, x, 3, held, {m.node_count()});
  double last = std::numeric_limits<double>::infinity();
  for (const int size : {50, 150, 400}) {
    const MatX kc = contact_stiffness(b.k, b.fixed, x, 3, held, {size});
    const double excess = (kc - whole).norm() / whole.norm();
    std::cout << "[contact] " << m.node_count() << "-node body, region of " << size << " nodes: " << excess
              << " of the whole body's K_c above it\n";
    EXPECT_GT(symmetric_eigenvalues(kc - whole).minCoeff(), -1e-9 * whole.norm());
    EXPECT_LT(excess, last);
    last = excess;
  }
}

// The holding force (sum over the held nodes of dE/dx, N) at the nonlinear static equilibrium with every held node
// moved by `offset` from rest.
Vec3 nonlinear_holding_force(const Body& b, const std::vector<int>& held, const Vec3& offset) {
  model::Problem p = model::make_problem(b.built.model);
  model::fix_nodes(p, b.clamped);
  model::fix_nodes(p, held);
  p.prescribed_positions = b.built.model->rest_positions();
  for (const int i : held) p.prescribed_positions.segment<3>(3 * i) += offset;
  StaticOptions o;
  o.newton.tolerance = 1e-12;
  o.check_stability = false;
  const StaticResult r = static_equilibrium(p, o);
  EXPECT_EQ(r.report.status, SolveStatus::kConverged) << r.report.message;
  const VecX g = b.built.model->gradient(r.positions);
  Vec3 f = Vec3::Zero();
  for (const int i : held) f += g.segment<3>(3 * i);
  return f;
}

// The curvature against the nonlinear equilibria it summarises: the holding force's second difference over the
// probe's offset, F(d p) + F(-d p) - F(d q) - F(-d q) = 4 d^2 T(., a, b) + O(d^4) with p = e_a + e_b, q = e_a - e_b
// (the envelope argument behind contact_curvature is what this checks: it never solves an equilibrium). A linear
// FEM model's energy is quadratic, so its curvature is zero.
TEST(ContactCurvature, IsTheSecondDifferenceOfNonlinearHoldingForces) {
  const Body b = body("any-nu-tet", 6, 4);
  const VecX& x = b.built.model->rest_positions();
  const std::vector<int> held = top_nodes(b.model.mesh, 0.004);
  const ContactResponse r = contact_response(b.k, b.fixed, x, 3, held);
  EXPECT_LT((r.stiffness - contact_stiffness(b.k, b.fixed, x, 3, held)).norm(), 1e-14 * r.stiffness.norm());
  for (const int i : held) EXPECT_EQ(r.modes.row(3 * i), Eigen::RowVector3d(1, 0, 0));
  for (const int i : b.clamped) EXPECT_EQ(r.modes.row(3 * i).norm(), 0.0);
  const MatX t = contact_curvature(*b.built.model, x, r.modes, 1e-6);
  ASSERT_EQ(t.rows(), 3);
  ASSERT_EQ(t.cols(), 9);
  const double d = 5e-5;
  for (const auto& [a, c] : {std::pair{0, 0}, {2, 2}, {0, 2}, {0, 1}}) {
    const Vec3 p = Vec3::Unit(a) + Vec3::Unit(c), q = Vec3::Unit(a) - Vec3::Unit(c);
    Vec3 second = nonlinear_holding_force(b, held, d * p) + nonlinear_holding_force(b, held, -d * p);
    if (a != c) second -= nonlinear_holding_force(b, held, d * q) + nonlinear_holding_force(b, held, -d * q);
    second /= 4.0 * d * d;
    const Vec3 column = t.col(3 * a + c);
    std::cout << "[curvature] T(., " << a << ", " << c << ") " << column.transpose() << " N/m^2, equilibria "
              << second.transpose() << "\n";
    EXPECT_LT((column - second).norm(), 5e-3 * t.norm());
    EXPECT_EQ(t.col(3 * a + c), t.col(3 * c + a));
  }
  for (int i = 0; i < 3; ++i)  // a third derivative of one energy: symmetric in all three indices
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(t(k, 3 * i + j), t(i, 3 * k + j), 1e-6 * t.norm());
  EXPECT_GT(t.norm(), 1e-3 * r.stiffness.norm() / 0.02);  // a body 2 cm tall stiffens by T d against K
  const Body linear = body("fem", 6, 4);
  const ContactResponse rl = contact_response(linear.k, linear.fixed, x, 3, held);
  EXPECT_LT(contact_curvature(*linear.built.model, x, rl.modes, 1e-6).norm(), 1e-6 * t.norm());
  EXPECT_THROW(contact_curvature(*b.built.model, x, r.modes, 0.0), InvalidArgument);
  EXPECT_THROW(contact_curvature(*b.built.model, x, r.modes.topRows(3), 1e-6), InvalidArgument);
}

TEST(ContactStiffness, RefusesWhatItCannotCondense) {
  const Body b = body("fem", 4, 2);
  const VecX& x = b.built.model->rest_positions();
  EXPECT_THROW(contact_stiffness(b.k, b.fixed, x, 3, {}), InvalidArgument);
  EXPECT_THROW(contact_stiffness(b.k, b.fixed, x, 3, {b.model.mesh.node_count()}), InvalidArgument);
  EXPECT_THROW(contact_stiffness(b.k, b.fixed, x, 3, {b.clamped[0]}), InvalidArgument);  // fixed
  const std::vector<char> loose(b.fixed.size(), 0);
  EXPECT_THROW(contact_stiffness(b.k, loose, x, 3, {top_nodes(b.model.mesh, 1e-9)}), SolverFailure);  // not held
}

}  // namespace
}  // namespace hooke::solve

namespace hooke::solve {
namespace {

// The compliance at a few nodes against the dense inverse of K on the free DOFs, and each node's 3 x 3 block against
// the condensed stiffness of that node alone (contact_stiffness: a Schur complement by another factorisation).
TEST(NodeCompliance, MatchesTheDenseInverseAndTheCondensedStiffness) {
  const Body b = body("any-nu-tet", 4, 3);
  const Eigen::Index nd = b.k.rows();
  std::vector<Eigen::Index> free;
  for (Eigen::Index i = 0; i < nd; ++i)
    if (!b.fixed[static_cast<size_t>(i)]) free.push_back(i);
  const MatX dense = MatX(b.k)(free, free);
  const MatX inverse = dense.llt().solve(MatX::Identity(dense.rows(), dense.rows()));
  std::vector<Eigen::Index> where(static_cast<size_t>(nd), -1);
  for (size_t r = 0; r < free.size(); ++r) where[static_cast<size_t>(free[r])] = static_cast<Eigen::Index>(r);
  const int n = static_cast<int>(nd / 3);
  const std::vector<int> nodes = {n - 1, n / 2, n - 7};
  NodeCompliance c(b.k, b.fixed, 3);
  const MatX block = c.block(nodes);
  ASSERT_EQ(block.rows(), 9);
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q)
      for (int a = 0; a < 3; ++a)
        for (int e = 0; e < 3; ++e) {
          const Eigen::Index i = where[static_cast<size_t>(3 * nodes[static_cast<size_t>(p)] + a)],
                             j = where[static_cast<size_t>(3 * nodes[static_cast<size_t>(q)] + e)];
          ASSERT_GE(i, 0);
          ASSERT_GE(j, 0);
          EXPECT_NEAR(block(3 * p + a, 3 * q + e), inverse(i, j), 1e-9 * inverse.norm());
        }
  for (int p = 0; p < 3; ++p) {
    const MatX kc =
        contact_stiffness(b.k, b.fixed, b.built.model->rest_positions(), 3, {nodes[static_cast<size_t>(p)]});
    EXPECT_LT((block.block<3, 3>(3 * p, 3 * p) * kc - MatX::Identity(3, 3)).norm(), 1e-8);
  }
  EXPECT_EQ(c.cached_nodes(), 3);
  EXPECT_THROW(c.block({n}), InvalidArgument);
  // A clamped node has no compliance.
  EXPECT_EQ(c.block({b.clamped.front()}).norm(), 0.0);
}

}  // namespace
}  // namespace hooke::solve
