// Identification checked against independent derivations: U(x) theta against the spring and volume blocks'
// gradients, the adjoint gradient of Eq. 1 against finite differences, and recovery of springs that made the data.
#include <gtest/gtest.h>
#include <algorithm>
#include <hooke/calibrate/cauchy_split.hpp>
#include <hooke/calibrate/method.hpp>
#include <hooke/calibrate/spring_model.hpp>
#include <hooke/core/error.hpp>
#include <hooke/identify/force_basis.hpp>
#include <hooke/identify/identify.hpp>
#include <hooke/identify/positions_objective.hpp>
#include <hooke/identify/scale_fit.hpp>
#include <hooke/identify/stacked_forces.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/problem.hpp>
#include <random>

#include "support/finite_difference.hpp"
#include "support/meshes.hpp"

using namespace hooke;
using identify::Parameters;

namespace {

VecX random_parameters(const identify::ParameterLayout& layout, unsigned seed, double k, double k_volume) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.5, 1.5), o(-0.05, 0.05);
  VecX theta(layout.size());
  for (int s = 0; s < layout.spring_count(); ++s) theta(s) = k * u(rng);
  for (int t = 0; t < layout.volume_count(); ++t) theta(layout.spring_count() + t) = k_volume * u(rng);
  for (int s = 0; s < layout.offset_count(); ++s)
    theta(layout.spring_count() + layout.volume_count() + s) = o(rng) * theta(s) * layout.rest_length(s);
  return theta;
}

VecX perturbed(const mesh::Mesh& mesh, double amount, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  VecX x = test::flat_positions(mesh);
  for (Eigen::Index i = 0; i < x.size(); ++i) x(i) += u(rng);
  return x;
}

// Reference cases made by a known spring model: bottom (z = 0) clamped, random forces on the other nodes.
std::vector<identify::ReferenceCase> cases_of(const mesh::Mesh& mesh, const calibrate::SpringModel& springs, int count,
                                              double force, unsigned seed) {
  const auto model = calibrate::make_model(mesh, springs);
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, force);
  std::vector<identify::ReferenceCase> out;
  for (int c = 0; c < count; ++c) {
    identify::ReferenceCase ref{"case " + std::to_string(c),
                                test::flat_positions(mesh),
                                VecX::Zero(model->dof_count()),
                                std::vector<char>(model->dof_count(), 0),
                                false,
                                {}};
    const int axis = c % 3;
    const double low = mesh.nodes.col(axis).minCoeff();
    for (int i = 0; i < mesh.node_count(); ++i)
      for (int d = 0; d < 3; ++d) {
        if (mesh.nodes(i, axis) < low + 1e-9)
          ref.fixed_dofs[3 * i + d] = 1;
        else
          ref.external_force(3 * i + d) = n(rng);
      }
    const solve::StaticResult r = identify::reference_equilibrium(model, ref, {}, ref.positions);
    EXPECT_EQ(r.report.status, solve::SolveStatus::kConverged);
    ref.positions = r.positions;
    out.push_back(ref);
  }
  return out;
}

// The objective's gradient at theta against central differences in 8 random parameters (steps of 1e-4 theta_j).
void expect_central_differences(identify::PositionsObjective& objective, const VecX& theta, const VecX& gradient,
                                unsigned seed) {
  std::mt19937 rng(seed);
  for (int trial = 0; trial < 8; ++trial) {
    const int j = static_cast<int>(rng() % static_cast<unsigned>(theta.size()));
    const double h = 1e-4 * theta(j);
    VecX tp = theta, tm = theta;
    tp(j) += h;
    tm(j) -= h;
    const double fd = (objective.value(tp) - objective.value(tm)) / (2.0 * h);
    EXPECT_NEAR(gradient(j), fd, 1e-5 * gradient.cwiseAbs().maxCoeff()) << "parameter " << j;
  }
}

// Reference cases under displacement control made by a known spring model: the nodes at the low end of an axis
// clamped, those at its high end held by an instrument and moved (rigidly by `move` x the extent, plus a random part of
// `jitter` x the extent per DOF so that springs between held nodes stretch too), the force holding each (dE/dx)
// recorded as measured. Case c presses along axis c % axes.
std::vector<identify::ReferenceCase> pressed_cases_of(const mesh::Mesh& mesh, const calibrate::SpringModel& springs,
                                                      int count, double move, double jitter, unsigned seed,
                                                      int axes = 3) {
  const auto model = calibrate::make_model(mesh, springs);
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<identify::ReferenceCase> out;
  for (int c = 0; c < count; ++c) {
    const auto dofs = static_cast<std::size_t>(model->dof_count());
    identify::ReferenceCase ref{"press " + std::to_string(c),
                                test::flat_positions(mesh),
                                VecX::Zero(model->dof_count()),
                                std::vector<char>(dofs, 0),
                                false,
                                std::vector<char>(dofs, 0)};
    const int axis = c % axes;
    const double low = mesh.nodes.col(axis).minCoeff(), high = mesh.nodes.col(axis).maxCoeff();
    Eigen::Vector3d direction(n(rng), n(rng), n(rng));
    direction *= move * (high - low) / direction.norm();
    for (int i = 0; i < mesh.node_count(); ++i)
      for (int d = 0; d < 3; ++d) {
        const auto dof = static_cast<std::size_t>(3 * i + d);
        if (mesh.nodes(i, axis) < low + 1e-9) {
          ref.fixed_dofs[dof] = 1;
        } else if (mesh.nodes(i, axis) > high - 1e-9) {
          ref.prescribed_dofs[dof] = 1;
          ref.positions(3 * i + d) += direction(d) + jitter * (high - low) * n(rng);
        }
      }
    const solve::StaticResult r = identify::reference_equilibrium(model, ref, {});  // ramped from rest
    EXPECT_EQ(r.report.status, solve::SolveStatus::kConverged) << r.report.message;
    ref.positions = r.positions;
    ref.external_force = identify::prescribed_part(ref, model->gradient(r.positions));
    out.push_back(ref);
  }
  return out;
}

}  // namespace

TEST(ForceBasis, EqualsTheBlocksGradientForEveryParameterKind) {
  const mesh::Mesh mesh = test::irregular_mesh(mesh::ElementKind::kTet, 2, 0.2);
  for (Parameters p : {Parameters::kSprings, Parameters::kSpringsVolume, Parameters::kSpringsVolumeRestLength}) {
    const identify::ParameterLayout layout = identify::parameter_layout(mesh, p);
    const VecX theta = random_parameters(layout, 3, 40.0, 2e-3);
    const VecX x = perturbed(mesh, 2e-4, 5);
    VecX forces(x.size());
    identify::ForceBasis(layout, x).apply(theta, forces);
    // the offsets fold into rest lengths l0 = L - delta / k (within [L/2, 2L] here)
    int clamped = -1;
    const auto model = calibrate::make_model(mesh, identify::spring_model(layout, theta, &clamped));
    EXPECT_EQ(clamped, 0);
    const VecX expected = model->gradient(x);
    EXPECT_LT((forces - expected).norm(), 1e-12 * expected.norm()) << identify::parameters_name(p);
  }
}

// The same for the large-strain term laws (docs/methods/large_strain.md): U(x) theta is still the model's gradient,
// the columns those of the layout's law, at a state stretched and compressed by 10 % of the edges.
TEST(ForceBasis, EqualsTheBlocksGradientForALargeStrainLaw) {
  const mesh::Mesh mesh = test::irregular_mesh(mesh::ElementKind::kTet, 2, 0.2);
  identify::ParameterLayout layout = identify::parameter_layout(mesh, Parameters::kSpringsVolume);
  layout.spring_exponent = 0.125;
  layout.volume_exponent = -1.5;
  const VecX theta = random_parameters(layout, 3, 40.0, 2e-3);
  const VecX x = perturbed(mesh, 2e-2, 5);
  VecX forces(x.size());
  identify::ForceBasis(layout, x).apply(theta, forces);
  const calibrate::SpringModel springs = identify::spring_model(layout, theta);
  EXPECT_EQ(springs.spring_exponent, 0.125);
  EXPECT_EQ(springs.volume_exponent, -1.5);
  const VecX expected = calibrate::make_model(mesh, springs)->gradient(x);
  EXPECT_LT((forces - expected).norm(), 1e-12 * expected.norm());
}

TEST(ForceBasis, TransposeIsTheAdjointOfApplyOnTheMaskedRows) {
  const mesh::Mesh mesh = test::irregular_mesh(mesh::ElementKind::kTet, 2, 0.2);
  const identify::ParameterLayout layout = identify::parameter_layout(mesh, Parameters::kSpringsVolumeRestLength);
  const VecX x = perturbed(mesh, 2e-4, 8), theta = random_parameters(layout, 4, 40.0, 2e-3);
  const VecX r = perturbed(mesh, 1.0, 9);
  std::vector<char> mask(x.size(), 1);
  for (std::size_t k = 0; k < mask.size(); k += 4) mask[k] = 0;
  VecX masked = r;
  for (std::size_t k = 0; k < mask.size(); ++k)
    if (!mask[k]) masked(static_cast<Eigen::Index>(k)) = 0.0;
  const identify::ForceBasis u(layout, x);
  VecX ut(layout.size()), ux(x.size());
  u.apply_transpose(masked, ut);
  u.apply(theta, ux);
  EXPECT_NEAR(ut.dot(theta), ux.dot(masked), 1e-12 * std::abs(ux.dot(masked)));
  VecX norms = VecX::Zero(layout.size());
  u.add_squared_column_norms(mask, norms);
  VecX e = VecX::Zero(layout.size()), col(x.size());
  for (int j : {0, layout.spring_count() + 1, layout.size() - 1}) {
    e.setZero();
    e(j) = 1.0;
    u.apply(e, col);
    for (std::size_t k = 0; k < mask.size(); ++k)
      if (!mask[k]) col(static_cast<Eigen::Index>(k)) = 0.0;
    EXPECT_NEAR(norms(j), col.squaredNorm(), 1e-12 * col.squaredNorm()) << j;
  }
}

// The stacked operator against each case's own ForceBasis with its supports' rows zeroed, for any split of the
// cases into groups: the products, the adjoint and the column norms.
TEST(StackedForceOperator, EqualsEachCasesBasisForAnyGrouping) {
  for (mesh::ElementKind kind : {mesh::ElementKind::kTet, mesh::ElementKind::kTriangle}) {
    const mesh::Mesh mesh = test::irregular_mesh(kind, 2, 0.2);
    const Parameters p = kind == mesh::ElementKind::kTet ? Parameters::kSpringsVolumeRestLength : Parameters::kSprings;
    const identify::ParameterLayout layout = identify::parameter_layout(mesh, p);
    std::vector<identify::ReferenceCase> cases;
    for (int c = 0; c < 5; ++c) {
      identify::ReferenceCase rc{std::string("c").append(std::to_string(c)),
                                 perturbed(mesh, 2e-4, 20 + c),
                                 perturbed(mesh, 1.0, 40 + c),
                                 std::vector<char>(static_cast<std::size_t>(mesh.dim() * mesh.node_count()), 0),
                                 false,
                                 {}};
      for (std::size_t k = static_cast<std::size_t>(c); k < rc.fixed_dofs.size(); k += 3 + c) rc.fixed_dofs[k] = 1;
      cases.push_back(rc);
    }
    std::vector<const identify::ReferenceCase*> pointers;
    for (const auto& c : cases) pointers.push_back(&c);
    const VecX theta = random_parameters(layout, 7, 40.0, 2e-3);
    // expected U theta and U^T y per case, masked
    for (int groups : {1, 2, 3, 5, 9}) {
      const identify::StackedForceOperator a(layout, pointers, groups);
      ASSERT_EQ(a.rows(), static_cast<Eigen::Index>(5 * mesh.dim() * mesh.node_count()));
      const VecX b = a.right_hand_side(pointers);
      VecX y, expected_t = VecX::Zero(layout.size()), t;
      a.apply(theta, y);
      VecX expected_norms = VecX::Zero(layout.size());
      for (int c = 0; c < 5; ++c) {
        const identify::ForceBasis basis(layout, cases[c].positions);
        VecX f(cases[c].positions.size()), ut(layout.size());
        basis.apply(theta, f);
        VecX masked_b = VecX::Zero(f.size()), yc(f.size());
        std::vector<char> free(f.size());
        for (Eigen::Index k = 0; k < f.size(); ++k) {
          const bool fixed = cases[c].fixed_dofs[static_cast<std::size_t>(k)];
          free[static_cast<std::size_t>(k)] = fixed ? 0 : 1;
          EXPECT_NEAR(y(a.row_of(c, k)), fixed ? 0.0 : f(k), 1e-12 * f.norm()) << groups << " " << c << " " << k;
          EXPECT_EQ(b(a.row_of(c, k)), fixed ? 0.0 : cases[c].external_force(k));
          yc(k) = fixed ? 0.0 : std::sin(1.0 + static_cast<double>(a.row_of(c, k)));
        }
        basis.apply_transpose(yc, ut);
        expected_t += ut;
        basis.add_squared_column_norms(free, expected_norms);
      }
      VecX probe(a.rows());
      for (Eigen::Index r = 0; r < probe.size(); ++r) probe(r) = std::sin(1.0 + static_cast<double>(r));
      a.apply_transpose(probe, t);
      EXPECT_LT((t - expected_t).norm(), 1e-12 * expected_t.norm()) << groups;
      EXPECT_LT((a.squared_column_norms() - expected_norms).norm(), 1e-12 * expected_norms.norm()) << groups;
    }
  }
}

TEST(ForceBasis, TrianglesTakeSpringsOnlyAndTetsTakeVolumeTerms) {
  const mesh::Mesh tri = mesh::rectangle_triangles(0.02, 0.02, 3, 3);
  EXPECT_EQ(identify::parameter_layout(tri, Parameters::kSprings).dim, 2);
  EXPECT_THROW(identify::parameter_layout(tri, Parameters::kSpringsVolume), InvalidArgument);
  const mesh::Mesh box = mesh::tet_box(0.01, 0.01, 0.01, 1, 1, 1);
  const auto layout = identify::parameter_layout(box, Parameters::kSpringsVolume);
  EXPECT_EQ(layout.spring_count(), 19);
  EXPECT_EQ(layout.volume_count(), 6);
}

// Eq. 1's adjoint gradient against central differences of the objective itself (each a converged equilibrium).
TEST(PositionsObjective, AdjointGradientMatchesFiniteDifferences) {
  const mesh::Mesh mesh = mesh::tet_box(0.02, 0.02, 0.02, 2, 2, 2);
  const identify::ParameterLayout layout = identify::parameter_layout(mesh, Parameters::kSpringsVolume);
  const VecX truth = random_parameters(layout, 11, 40.0, 2e-3);
  auto cases = cases_of(mesh, identify::spring_model(layout, truth), 2, 0.02, 12);
  solve::StaticOptions statics;
  statics.newton.tolerance = 1e-13;
  identify::PositionsObjective objective(mesh, layout, cases, statics);
  const VecX theta = random_parameters(layout, 13, 40.0, 2e-3);  // not the truth: G > 0
  VecX gradient;
  const double g = objective.value(theta, &gradient);
  ASSERT_GT(g, 1e-6);
  expect_central_differences(objective, theta, gradient, 1);
}

// Data made by a spring model with random k and k_V: Eq. 2 finds them again (the model is in its own class).
TEST(Identify, ForcesObjectiveRecoversTheSpringsThatMadeTheData) {
  const mesh::Mesh mesh = test::irregular_mesh(mesh::ElementKind::kTet, 2, 0.2);
  const identify::ParameterLayout layout = identify::parameter_layout(mesh, Parameters::kSpringsVolume);
  const VecX truth = random_parameters(layout, 21, 40.0, 2e-3);
  identify::IdentifyOptions options;
  options.objective = identify::Objective::kForces;  // Eq. 2 alone
  options.parameters = Parameters::kSpringsVolume;
  const identify::Identification id =
      identify::identify(mesh, cases_of(mesh, identify::spring_model(layout, truth), 6, 0.01, 22), options);
  EXPECT_TRUE(id.report.converged);
  EXPECT_LT(id.report.force_residual, 1e-8);
  EXPECT_LT((id.theta - truth).cwiseQuotient(truth).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_NEAR(id.report.min_stiffness, truth.head(layout.spring_count()).minCoeff(), 1e-6 * 40.0);
  // from a start model (as hooke identify starts from the analytic model): the same minimiser
  VecX start = truth;
  for (Eigen::Index j = 0; j < start.size(); ++j) start(j) *= j % 2 ? 1.5 : 0.6;
  options.start_model = identify::spring_model(layout, start);
  const identify::Identification warm =
      identify::identify(mesh, cases_of(mesh, identify::spring_model(layout, truth), 6, 0.01, 22), options);
  EXPECT_TRUE(warm.report.converged);
  EXPECT_LT((warm.theta - truth).cwiseQuotient(truth).cwiseAbs().maxCoeff(), 1e-6);
}

// Below nu = 1/4 the volume terms must be negative. Data made by a model with k_V < 0 (still positive definite)
// is recovered exactly with negative_volume, and not without it (k_V >= 0 cannot reach it).
TEST(Identify, NegativeVolumeTermsAreRecoveredOnlyWhenAllowed) {
  const mesh::Mesh mesh = test::irregular_mesh(mesh::ElementKind::kTet, 2, 0.2);
  identify::ParameterLayout layout = identify::parameter_layout(mesh, Parameters::kSpringsVolume);
  layout.negative_volume = true;
  // the unclamped Cauchy split at nu = 0.2 (docs/methods/any_nu.md): springs of a nu = 1/4 solid plus k_V < 0 on
  // every tet; its clamped static solves converge (cases_of checks), so the model resists these loads
  const material::Material soft{material::Law::kLinear, 1000.0, 0.2};
  const calibrate::CauchySplit split = calibrate::unclamped_cauchy_split(soft);
  calibrate::SpringModel springs = calibrate::calibrate(
      mesh, {{material::Law::kLinear, split.spring_youngs_modulus, 0.25}}, calibrate::Method::kLloydTet);
  springs.volume_tets = layout.tets;
  springs.rest_volume = layout.rest_volume;
  springs.volume_stiffness = split.volume_lambda * layout.rest_volume;
  const VecX truth = identify::parameters_of(layout, springs);
  ASSERT_LT(truth.tail(layout.volume_count()).maxCoeff(), 0.0);
  const auto cases = cases_of(mesh, springs, 6, 1e-4, 24);
  identify::IdentifyOptions options;
  options.objective = identify::Objective::kForces;  // Eq. 2 alone
  options.parameters = Parameters::kSpringsVolume;
  const identify::Identification bounded = identify::identify(mesh, cases, options);
  EXPECT_GT(bounded.report.force_residual, 1e-3);
  EXPECT_EQ(bounded.theta.tail(layout.volume_count()).minCoeff(), 0.0);
  options.negative_volume = true;
  const identify::Identification free = identify::identify(mesh, cases, options);
  EXPECT_TRUE(free.report.converged);
  EXPECT_LT(free.report.force_residual, 1e-8);
  const int ns = layout.spring_count(), nt = layout.volume_count();
  const double kv = truth.tail(nt).cwiseAbs().maxCoeff();
  EXPECT_LT((free.theta - truth).head(ns).cwiseQuotient(truth.head(ns)).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT((free.theta - truth).tail(nt).cwiseAbs().maxCoeff(), 1e-6 * kv);
  // Eq. 1 keeps them: its start (the exact Eq. 2 fit, better than the bounded one offered) is not clamped to k_V >= 0
  options.objective = identify::Objective::kPositions;
  options.position_iterations = 5;
  options.start_model = bounded.springs;
  const identify::Identification positions = identify::identify(mesh, cases, options);
  EXPECT_LT(positions.report.position_history.back(), 1e-10);
  EXPECT_LT((positions.theta - truth).tail(nt).cwiseAbs().maxCoeff(), 1e-4 * kv);
}

// A self-stressed model, like Lloyd's prestrained square (Eq. 11): tensions t in the null space of the spring
// network's equilibrium matrix, rest lengths l0 = L - t/k. The rest mesh is still an equilibrium, and Eq. 2 with
// rest lengths finds k, k_V and l0 again.
TEST(Identify, RestLengthsOfASelfStressedModelAreRecovered) {
  const mesh::Mesh mesh = test::irregular_mesh(mesh::ElementKind::kTet, 2, 0.2);
  const identify::ParameterLayout layout = identify::parameter_layout(mesh, Parameters::kSpringsVolumeRestLength);
  VecX truth = random_parameters(layout, 31, 40.0, 2e-3);
  const int ns = layout.spring_count(), offsets = ns + layout.volume_count();
  MatX equilibrium(3 * mesh.node_count(), ns);  // column s: the unit tension of spring s at the nodes
  const identify::ForceBasis basis(layout, test::flat_positions(mesh));
  VecX e = VecX::Zero(layout.size()), column(equilibrium.rows());
  for (int s = 0; s < ns; ++s) {
    e.setZero();
    e(offsets + s) = 1.0;
    basis.apply(e, column);
    equilibrium.col(s) = column;
  }
  const MatX self_stress = Eigen::FullPivLU<MatX>(equilibrium).kernel();
  ASSERT_GT(self_stress.cols(), 5);
  VecX t = self_stress * VecX::LinSpaced(self_stress.cols(), -1.0, 1.0);
  const VecX limit = truth.head(ns).cwiseProduct(layout.rest_length);
  t *= 0.05 / t.cwiseQuotient(limit).cwiseAbs().maxCoeff();  // |t| <= 5 % of k L: l0 within 5 % of L
  ASSERT_LT((equilibrium * t).norm(), 1e-12 * limit.norm());
  truth.tail(ns) = t;
  const calibrate::SpringModel made = identify::spring_model(layout, truth);
  identify::IdentifyOptions options;
  options.objective = identify::Objective::kForces;  // Eq. 2 alone
  options.parameters = Parameters::kSpringsVolumeRestLength;
  const identify::Identification id = identify::identify(mesh, cases_of(mesh, made, 6, 0.01, 32), options);
  EXPECT_TRUE(id.report.least_squares.converged)
      << id.report.least_squares.iterations << " iterations, projected gradient "
      << id.report.least_squares.projected_gradient;
  EXPECT_LT(id.report.force_residual, 1e-7);
  EXPECT_EQ(id.report.clamped_rest_lengths, 0);
  EXPECT_GT((made.rest_length - layout.rest_length).cwiseQuotient(layout.rest_length).cwiseAbs().maxCoeff(), 0.01);
  // the self-stress directions are the worst-conditioned of the problem (only the rest case and the small loads see
  // them): at the solver's tolerance (projected gradient 1e-9) l0 is known to a few parts per million
  EXPECT_LT((id.springs.rest_length - made.rest_length).cwiseQuotient(made.rest_length).cwiseAbs().maxCoeff(), 1e-5);
  EXPECT_LT((id.springs.stiffness - made.stiffness).cwiseQuotient(made.stiffness).cwiseAbs().maxCoeff(), 1e-5);
  EXPECT_LT(
      (id.springs.volume_stiffness - made.volume_stiffness).cwiseQuotient(made.volume_stiffness).cwiseAbs().maxCoeff(),
      1e-5);
}

TEST(Identify, PositionsObjectiveDoesNotLoseWhatTheForcesFitFound) {
  const mesh::Mesh mesh = mesh::tet_box(0.02, 0.02, 0.02, 2, 2, 2);
  const identify::ParameterLayout layout = identify::parameter_layout(mesh, Parameters::kSprings);
  const VecX truth = random_parameters(layout, 41, 40.0, 0.0);
  // data from a model with volume terms: springs alone cannot fit it exactly
  const identify::ParameterLayout full = identify::parameter_layout(mesh, Parameters::kSpringsVolume);
  VecX made = random_parameters(full, 42, 40.0, 2e-3);
  made.head(layout.spring_count()) = truth;
  const auto cases = cases_of(mesh, identify::spring_model(full, made), 6, 0.005, 43);
  identify::IdentifyOptions options;
  options.objective = identify::Objective::kPositions;
  options.position_iterations = 15;
  const identify::Identification id = identify::identify(mesh, cases, options);
  ASSERT_GE(id.report.position_history.size(), 2u);
  EXPECT_LT(id.report.position_history.back(), 0.7 * id.report.position_history.front());
  EXPECT_GT(id.report.static_solves, 0);
}

TEST(Identify, RejectsCasesOfTheWrongSizeOrAllHeldOut) {
  const mesh::Mesh mesh = mesh::tet_box(0.01, 0.01, 0.01, 1, 1, 1);
  identify::ReferenceCase bad{"short", VecX::Zero(3), VecX::Zero(3), std::vector<char>(3, 0), false, {}};
  EXPECT_THROW(identify::identify(mesh, {bad}), InvalidArgument);
  identify::ReferenceCase held{"held", test::flat_positions(mesh), VecX::Zero(24), std::vector<char>(24, 0), true, {}};
  EXPECT_THROW(identify::identify(mesh, {held}), InvalidArgument);
  held.held_out = false;
  identify::IdentifyOptions options;
  options.objective = identify::Objective::kForces;  // Eq. 2 alone
  for (double tolerance : {0.0, 1.0, std::nan("")}) {
    options.least_squares.tolerance = tolerance;
    EXPECT_THROW(identify::identify(mesh, {held}, options), InvalidArgument) << tolerance;
  }
}

// Parameters::kScale: data made by a model recovers the factor that was taken off it (geometrically nonlinear
// springs at a few % strain: the fixed point, not only the linear closed form), and the refusals.
TEST(Identify, ScaleRecoversTheFactorTakenOffTheModelThatMadeTheData) {
  const mesh::Mesh mesh = test::irregular_mesh(mesh::ElementKind::kTet, 2, 0.2);
  const identify::ParameterLayout layout = identify::parameter_layout(mesh, Parameters::kSpringsVolume);
  const calibrate::SpringModel truth = identify::spring_model(layout, random_parameters(layout, 31, 40.0, 2e-3));
  std::vector<identify::ReferenceCase> cases = cases_of(mesh, truth, 4, 0.05, 32);
  cases.back().held_out = true;
  identify::IdentifyOptions options;
  options.objective = identify::Objective::kForces;  // Eq. 2 alone
  options.parameters = Parameters::kScale;
  options.start_model = identify::scaled(truth, 1.0 / 1.3);
  const identify::Identification id = identify::identify(mesh, cases, options);
  EXPECT_TRUE(id.report.converged);
  EXPECT_NEAR(id.report.scale_factor, 1.3, 1e-8);
  EXPECT_LT(id.report.position_history.back(), 1e-16);
  EXPECT_GT(id.report.position_history.front(), 1e-3);
  EXPECT_LT((id.springs.stiffness - truth.stiffness).cwiseAbs().maxCoeff(), 1e-8 * 40.0);
  EXPECT_LT((id.springs.volume_stiffness - truth.volume_stiffness).cwiseAbs().maxCoeff(), 1e-8 * 2e-3);
  // The linear closed form alone is not the answer at this strain: more than one update was needed.
  EXPECT_GT(id.report.position_iterations, 1);

  options.start_model.reset();
  EXPECT_THROW(identify::identify(mesh, cases, options), InvalidArgument);
  EXPECT_THROW(identify::parameter_layout(mesh, Parameters::kScale), InvalidArgument);
  EXPECT_EQ(identify::parameters_from_name("scale"), Parameters::kScale);
}

// Eq. 1 with displacement-controlled cases (the force term, whose adjoint shares the positions' solve) beside a case
// under forces: the gradient against central differences.
TEST(PositionsObjective, AdjointGradientMatchesFiniteDifferencesUnderDisplacementControl) {
  const mesh::Mesh mesh = mesh::tet_box(0.02, 0.02, 0.02, 2, 2, 2);
  const identify::ParameterLayout layout = identify::parameter_layout(mesh, Parameters::kSpringsVolume);
  const calibrate::SpringModel truth = identify::spring_model(layout, random_parameters(layout, 11, 40.0, 2e-3));
  std::vector<identify::ReferenceCase> cases = pressed_cases_of(mesh, truth, 2, 0.05, 0.01, 14);
  cases.push_back(cases_of(mesh, truth, 1, 0.02, 12).front());
  solve::StaticOptions statics;
  statics.newton.tolerance = 1e-13;
  identify::PositionsObjective objective(mesh, layout, cases, statics);
  const VecX theta = random_parameters(layout, 13, 40.0, 2e-3);
  VecX gradient;
  const double g = objective.value(theta, &gradient);
  ASSERT_GT(g, 1e-6);
  expect_central_differences(objective, theta, gradient, 2);
  // At the springs that made the data both terms vanish: positions and forces are matched.
  EXPECT_LT(objective.value(identify::parameters_of(layout, truth)), 1e-16);
  std::vector<double> force_errors;
  const std::vector<double> errors = identify::position_errors(mesh, truth, cases, statics, &force_errors);
  EXPECT_LT(*std::max_element(errors.begin(), errors.end()), 1e-8);
  EXPECT_LT(std::max(force_errors[0], force_errors[1]), 1e-8);
  EXPECT_EQ(force_errors[2], -1.0);  // the case under forces measures no instrument
}

// Under displacement control the positions alone cannot fix the stiffness's scale; the measured forces do. Eq. 2 on
// presses made by a known model recovers its springs and volume terms, and the scale fit its factor in one step.
TEST(Identify, PressesWithMeasuredForcesRecoverTheSpringsThatMadeThem) {
  const mesh::Mesh mesh = test::irregular_mesh(mesh::ElementKind::kTet, 2, 0.2);
  const identify::ParameterLayout layout = identify::parameter_layout(mesh, Parameters::kSpringsVolume);
  const VecX truth = random_parameters(layout, 21, 40.0, 2e-3);
  const auto cases = pressed_cases_of(mesh, identify::spring_model(layout, truth), 6, 0.02, 0.002, 23);
  identify::IdentifyOptions options;
  options.objective = identify::Objective::kForces;
  options.parameters = Parameters::kSpringsVolume;
  const identify::Identification id = identify::identify(mesh, cases, options);
  EXPECT_TRUE(id.report.converged);
  EXPECT_LT(id.report.force_residual, 1e-8);
  EXPECT_LT((id.theta - truth).cwiseQuotient(truth).cwiseAbs().maxCoeff(), 1e-6);

  options.parameters = Parameters::kScale;
  options.start_model = identify::scaled(identify::spring_model(layout, truth), 1.0 / 1.3);
  const identify::Identification scale = identify::identify(mesh, cases, options);
  EXPECT_NEAR(scale.report.scale_factor, 1.3, 1e-10);
  EXPECT_EQ(scale.report.position_iterations, 1);
  EXPECT_LT(scale.report.position_history.back(), 1e-12);  // zero up to the cancellation in |cR - R_ref|^2
  std::vector<identify::ReferenceCase> mixed = cases;
  mixed.push_back(cases_of(mesh, identify::spring_model(layout, truth), 1, 0.01, 24).front());
  EXPECT_THROW(identify::identify(mesh, mixed, options), InvalidArgument);  // one control per scale fit
}

// A rigid plate leaves the springs between held nodes unstretched: their columns are round-off, and Eq. 2 keeps
// them at the start model's stiffness instead of letting them absorb the residual (they reached 1e14 N/m so). Every
// case presses the same face, so the springs on it are held in all of them.
TEST(Identify, SpringsBetweenNodesOfARigidPlateKeepTheirStartStiffness) {
  const mesh::Mesh mesh = test::irregular_mesh(mesh::ElementKind::kTet, 2, 0.2);
  const identify::ParameterLayout layout = identify::parameter_layout(mesh, Parameters::kSpringsVolume);
  const VecX truth = random_parameters(layout, 21, 40.0, 2e-3);
  const auto cases = pressed_cases_of(mesh, identify::spring_model(layout, truth), 3, 0.02, 0.0, 25, 1);
  identify::IdentifyOptions options;
  options.objective = identify::Objective::kForces;
  options.parameters = Parameters::kSpringsVolume;
  options.start_model = identify::spring_model(layout, VecX(1.2 * truth));
  const identify::Identification id = identify::identify(mesh, cases, options);
  int unstretched = 0;
  const auto held = [](const identify::ReferenceCase& c, int node) {
    return c.fixed_dofs[static_cast<std::size_t>(3 * node)] || c.prescribed_dofs[static_cast<std::size_t>(3 * node)];
  };
  for (int s = 0; s < layout.spring_count(); ++s) {
    const auto [i, j] = layout.pairs[static_cast<std::size_t>(s)];
    bool held_everywhere = true;
    for (const auto& c : cases) held_everywhere = held_everywhere && held(c, i) && held(c, j);
    if (!held_everywhere) continue;
    ++unstretched;
    EXPECT_NEAR(id.theta(s), 1.2 * truth(s), 1e-9 * truth(s)) << "spring " << s;
  }
  EXPECT_GT(unstretched, 0);
  EXPECT_LT(id.theta.head(layout.spring_count()).maxCoeff(), 2.0 * truth.maxCoeff());
}
