#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/solve/strain_response.hpp>

namespace hooke::solve {

double traction_for_strain(const mesh::Mesh& mesh, const std::vector<material::Material>& materials,
                           model::LoadKind kind, double strain) {
  return linear_response_for_strain(mesh, materials, kind, strain).traction_pa;
}

StrainResponse linear_response_for_strain(const mesh::Mesh& mesh, const std::vector<material::Material>& materials,
                                          model::LoadKind kind, double strain) {
  return std::move(linear_responses_for_strain(mesh, materials, {kind}, strain).front());
}

std::vector<StrainResponse> linear_responses_for_strain(const mesh::Mesh& mesh,
                                                        const std::vector<material::Material>& materials,
                                                        const std::vector<model::LoadKind>& kinds, double strain) {
  if (!(strain > 0.0) || !std::isfinite(strain)) throw InvalidArgument("the strain must be a positive number");
  model::Problem problem = model::make_problem(fem::linear_model(mesh, materials));
  std::vector<model::LoadCase> units;
  std::vector<VecX> forces;
  for (model::LoadKind kind : kinds) {
    units.push_back(model::make_load_case(mesh, kind, 1.0, materials.at(0).thickness));
    // Every kind clamps the same bottom nodes (make_load_case), so one factorisation serves them all.
    if (units.back().fixed_nodes != units.front().fixed_nodes)
      throw InvalidArgument("linear_responses_for_strain: load cases with different supports");
    forces.push_back(units.back().nodal_forces);
  }
  if (!units.empty()) model::fix_nodes(problem, units.front().fixed_nodes);
  for (VecX& f : forces) model::zero_fixed_forces(problem.fixed_dofs, f);
  std::vector<StaticResult> fem = linear_statics(problem, forces);
  std::vector<StrainResponse> out;
  const VecX& rest = problem.model->rest_positions();
  for (size_t k = 0; k < kinds.size(); ++k) {
    StrainResponse r;
    r.fem = std::move(fem[k]);
    require_converged(r.fem.report);
    const double u = model::mean_top_displacement(units[k], problem, r.fem.positions);
    if (!(u > 0.0)) throw SolverFailure("the unit load produced no displacement along the load direction");
    const double t = strain * units[k].height / u;
    r.traction_pa = t;
    r.fem.positions = rest + t * (r.fem.positions - rest);
    SolveReport& rep = r.fem.report;
    rep.residual *= t;
    rep.reference_force *= t;
    for (double& h : rep.residual_history) h *= t;
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace hooke::solve
