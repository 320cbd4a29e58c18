#include <cmath>
#include <hooke/calibrate/spring_model.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/sparse_cholesky.hpp>
#include <hooke/identify/force_basis.hpp>
#include <hooke/identify/positions_objective.hpp>
#include <hooke/model/free_map.hpp>
#include <hooke/model/problem.hpp>
#include <limits>

namespace hooke::identify {

namespace {
double relative_distance(const VecX& x, const VecX& reference, const VecX& rest) {
  return (x - reference).norm() / std::max((reference - rest).norm(), std::numeric_limits<double>::min());
}
}  // namespace

solve::StaticResult reference_equilibrium(std::shared_ptr<const model::Model> model, const ReferenceCase& reference,
                                          const solve::StaticOptions& statics, const VecX& start) {
  model::Problem problem = model::make_problem(std::move(model));
  problem.fixed_dofs = reference.fixed_dofs;
  problem.prescribed_positions = reference.positions;
  problem.external_force = reference.external_force;
  model::zero_fixed_forces(problem);
  solve::StaticOptions options = statics;
  options.start = start.size() ? start : reference.positions;
  return solve::static_equilibrium(problem, options);
}

std::vector<double> position_errors(const mesh::Mesh& mesh, const calibrate::SpringModel& springs,
                                    const std::vector<ReferenceCase>& cases, const solve::StaticOptions& statics) {
  const auto model = calibrate::make_model(mesh, springs);
  std::vector<double> out;
  for (const auto& c : cases) {
    validate_reference(c, model->dof_count());
    const solve::StaticResult result = reference_equilibrium(model, c, statics);
    out.push_back(result.report.status == solve::SolveStatus::kConverged
                      ? relative_distance(result.positions, c.positions, model->rest_positions())
                      : std::numeric_limits<double>::infinity());
  }
  return out;
}

PositionsObjective::PositionsObjective(const mesh::Mesh& mesh, const ParameterLayout& layout,
                                       std::vector<ReferenceCase> cases, const solve::StaticOptions& statics)
    : m_mesh(mesh), m_layout(layout), m_cases(std::move(cases)), m_statics(statics) {
  if (layout.offset_count())
    throw InvalidArgument("the positions objective takes fixed rest lengths (fit them with the forces objective)");
  const VecX rest = mesh::flat_positions(mesh);
  for (const auto& c : m_cases) {
    validate_reference(c, rest.size());
    m_reference += (c.positions - rest).squaredNorm();
  }
  if (!(m_reference > 0.0)) throw InvalidArgument("the positions objective needs at least one deformed case");
  m_equilibria.resize(m_cases.size());
  m_case_errors.assign(m_cases.size(), 0.0);
}

double PositionsObjective::value(const VecX& theta, VecX* gradient) {
  const auto model = calibrate::make_model(m_mesh, spring_model(m_layout, theta));
  if (gradient) gradient->setZero(m_layout.size());
  double sum = 0.0;
  for (std::size_t c = 0; c < m_cases.size(); ++c) {
    const ReferenceCase& ref = m_cases[c];
    // With a gradient, the adjoint's Cholesky factorisation of H at the equilibrium tests its stability (a failed
    // factorisation returns +infinity below), so the static solver's own stability test is skipped.
    solve::StaticOptions statics = m_statics;
    if (gradient) statics.check_stability = false;
    const solve::StaticResult result =
        reference_equilibrium(model, ref, statics, m_equilibria[c].size() ? m_equilibria[c] : ref.positions);
    ++m_solves;
    if (result.report.status != solve::SolveStatus::kConverged) return std::numeric_limits<double>::infinity();
    m_equilibria[c] = result.positions;
    const VecX miss = result.positions - ref.positions;
    m_case_errors[c] = relative_distance(result.positions, ref.positions, model->rest_positions());
    sum += miss.squaredNorm();
    if (!gradient) continue;
    model::Problem problem = model::make_problem(model);
    problem.fixed_dofs = ref.fixed_dofs;
    const model::FreeMap free(model::free_dofs(problem), model->dof_count());
    SparseCholesky cholesky;
    if (!cholesky.factorize(free.restrict(model->hessian(result.positions))))
      return std::numeric_limits<double>::infinity();
    const VecX lambda_free = cholesky.solve(free.restrict(miss));
    VecX lambda = VecX::Zero(model->dof_count());  // zero on the supports: their rows do not count
    for (int i = 0; i < free.size(); ++i) lambda(free.free[i]) = lambda_free(i);
    VecX part(m_layout.size());
    ForceBasis(m_layout, result.positions).apply_transpose(lambda, part);
    *gradient -= 2.0 * part;
  }
  if (gradient) *gradient /= m_reference;
  return sum / m_reference;
}

}  // namespace hooke::identify
