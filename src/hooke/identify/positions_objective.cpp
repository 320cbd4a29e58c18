#include <algorithm>
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

// The total over the nodes of a flat per-DOF vector (dim entries).
VecX node_sum(const VecX& v, int dim) {
  VecX sum = VecX::Zero(dim);
  for (Eigen::Index n = 0; n < v.size() / dim; ++n) sum += v.segment(dim * n, dim);
  return sum;
}
}  // namespace

double reaction_error(const ReferenceCase& reference, const VecX& gradient, int dim) {
  if (!has_prescribed(reference)) return -1.0;
  const VecX measured = node_sum(prescribed_part(reference, reference.external_force), dim);
  const VecX miss = node_sum(prescribed_part(reference, gradient), dim) - measured;
  return miss.norm() / std::max(measured.norm(), std::numeric_limits<double>::min());
}

solve::StaticResult reference_equilibrium(std::shared_ptr<const model::Model> model, const ReferenceCase& reference,
                                          const solve::StaticOptions& statics, const VecX& start) {
  model::Problem problem = model::make_problem(std::move(model));
  problem.fixed_dofs = held_dofs(reference);
  problem.prescribed_positions = reference.positions;
  problem.external_force = reference.external_force;
  model::zero_fixed_forces(problem);
  solve::StaticOptions options = statics;
  if (start.size())
    options.start = start;
  else if (has_prescribed(reference))
    options.ramp_prescribed = true;  // from rest, the held nodes moved with the load factor (as `hooke compare`)
  else
    options.start = reference.positions;
  return solve::static_equilibrium(problem, options);
}

std::vector<double> position_errors(const mesh::Mesh& mesh, const calibrate::SpringModel& springs,
                                    const std::vector<ReferenceCase>& cases, const solve::StaticOptions& statics,
                                    std::vector<double>* force_errors) {
  const auto model = calibrate::make_model(mesh, springs);
  std::vector<double> out;
  if (force_errors) force_errors->clear();
  for (const auto& c : cases) {
    validate_reference(c, model->dof_count());
    const solve::StaticResult result = reference_equilibrium(model, c, statics);
    const bool ok = result.report.status == solve::SolveStatus::kConverged;
    out.push_back(ok ? relative_distance(result.positions, c.positions, model->rest_positions())
                     : std::numeric_limits<double>::infinity());
    if (force_errors)
      force_errors->push_back(!has_prescribed(c) ? -1.0
                              : ok               ? reaction_error(c, model->gradient(result.positions), model->dim())
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
  const auto prescribed =
      std::count_if(m_cases.begin(), m_cases.end(), [](const auto& c) { return has_prescribed(c); });
  m_force_weights.assign(m_cases.size(), 0.0);
  for (std::size_t c = 0; c < m_cases.size(); ++c) {
    if (!has_prescribed(m_cases[c])) continue;
    const ReferenceCase& ref = m_cases[c];
    const double measured =
        node_sum(prescribed_part(ref, ref.external_force), static_cast<int>(rest.size() / mesh.node_count()))
            .squaredNorm();
    if (!(measured > 0.0))
      throw InvalidArgument("reference case '" + m_cases[c].name +
                            "' prescribes positions but measures no force where it does");
    m_force_weights[c] = 1.0 / (static_cast<double>(prescribed) * measured);
  }
  m_equilibria.resize(m_cases.size());
  m_case_errors.assign(m_cases.size(), 0.0);
}

double PositionsObjective::value(const VecX& theta, VecX* gradient) {
  const auto model = calibrate::make_model(m_mesh, spring_model(m_layout, theta));
  if (gradient) gradient->setZero(m_layout.size());
  double sum = 0.0, force_sum = 0.0;
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
    const bool prescribed = has_prescribed(ref);
    VecX force_miss;  // S^T S (R(theta) - R_ref): the total force's miss on every prescribed DOF of its axis
    if (prescribed) {
      const int d = model->dim();
      const VecX total =
          node_sum(prescribed_part(ref, VecX(model->gradient(result.positions) - ref.external_force)), d);
      force_sum += m_force_weights[c] * total.squaredNorm();
      force_miss = VecX::Zero(model->dof_count());
      for (std::size_t k = 0; k < ref.prescribed_dofs.size(); ++k)
        if (ref.prescribed_dofs[k]) force_miss(static_cast<Eigen::Index>(k)) = total(static_cast<Eigen::Index>(k) % d);
    }
    if (!gradient) continue;
    model::Problem problem = model::make_problem(model);
    problem.fixed_dofs = held_dofs(ref);
    const model::FreeMap free(model::free_dofs(problem), model->dof_count());
    const SparseMatrix hessian = model->hessian(result.positions);
    SparseCholesky cholesky;
    if (!cholesky.factorize(free.restrict(hessian))) return std::numeric_limits<double>::infinity();
    // Positions: dG/dtheta = -2/G_ref U^T lambda, H_FF lambda_F = (x - p)_F.
    VecX rhs = free.restrict(miss) / m_reference;
    // Forces (prescribed DOFs P): R = U_P(x) theta, dR/dtheta = U_P - H_PF H_FF^-1 U_F, so
    // d|R - R_ref|^2/dtheta = 2 U^T v with v_P = e, v_F = -H_FF^-1 H_FP e; both adjoints share one solve.
    VecX v = VecX::Zero(model->dof_count());
    if (prescribed) {
      rhs += m_force_weights[c] * free.restrict(VecX(hessian * force_miss));
      v = m_force_weights[c] * force_miss;
    }
    const VecX lambda_free = cholesky.solve(rhs);
    for (int i = 0; i < free.size(); ++i) v(free.free[i]) -= lambda_free(i);  // zero on the supports
    VecX part(m_layout.size());
    ForceBasis(m_layout, result.positions).apply_transpose(v, part);
    *gradient += 2.0 * part;
  }
  return sum / m_reference + force_sum;
}

}  // namespace hooke::identify
