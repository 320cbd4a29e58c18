#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/name_table.hpp>
#include <hooke/experiments/load_case.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/mesh/topology.hpp>
#include <hooke/solve/static_equilibrium.hpp>

namespace hooke::experiments {

namespace {
constexpr NameTable<LoadKind, 3> kLoadKinds{
    "load case", {{{LoadKind::kStretch, "stretch"}, {LoadKind::kCompress, "compress"}, {LoadKind::kShear, "shear"}}}};
}  // namespace

LoadKind load_kind_from_name(std::string_view name) { return kLoadKinds.from_name(name); }
std::string_view load_kind_name(LoadKind kind) { return kLoadKinds.name(kind); }

LoadCase make_load_case(const mesh::Mesh& mesh, LoadKind kind, double traction_pa, double thickness) {
  if (!std::isfinite(traction_pa)) throw InvalidArgument("the traction must be a finite number of pascals");
  const int d = mesh.dim(), up = d - 1;
  LoadCase lc;
  lc.kind = kind;
  lc.traction_pa = traction_pa;
  lc.direction = VecX::Zero(d);
  switch (kind) {
    case LoadKind::kStretch: lc.direction(up) = 1.0; break;
    case LoadKind::kCompress: lc.direction(up) = -1.0; break;
    case LoadKind::kShear: lc.direction(d == 2 ? 0 : 1) = 1.0; break;
  }
  const double top = mesh.nodes.col(up).maxCoeff(), bottom = mesh.nodes.col(up).minCoeff();
  const RowMatXi facets = mesh::boundary_facets(mesh);
  const VecX measure = mesh::facet_measures(mesh, facets);
  lc.height = top - bottom;
  double tol = 1e-6 * mesh::bounding_box_diagonal(mesh);
  bool flat_top = false;
  for (Eigen::Index f = 0; f < facets.rows() && !flat_top; ++f) {
    bool on_top = true;
    for (Eigen::Index k = 0; k < facets.cols(); ++k) on_top = on_top && mesh.nodes(facets(f, k), up) >= top - tol;
    flat_top = on_top;
  }
  if (!flat_top) tol = kEndBand * lc.height;  // a curved body: its end bands
  for (int i = 0; i < mesh.node_count(); ++i) {
    if (mesh.nodes(i, up) <= bottom + tol) lc.fixed_nodes.push_back(i);
    if (mesh.nodes(i, up) >= top - tol) lc.top_nodes.push_back(i);
  }
  lc.nodal_forces = VecX::Zero(d * mesh.node_count());
  int loaded = 0;
  for (Eigen::Index f = 0; f < facets.rows(); ++f) {
    bool on_top = true;
    for (Eigen::Index k = 0; k < facets.cols(); ++k) on_top = on_top && mesh.nodes(facets(f, k), up) >= top - tol;
    if (!on_top) continue;
    ++loaded;
    const double area = measure(f) * (d == 2 ? thickness : 1.0);
    lc.top_area += area;
    const double share = traction_pa * area / static_cast<double>(facets.cols());
    for (Eigen::Index k = 0; k < facets.cols(); ++k)
      for (int c = 0; c < d; ++c) lc.nodal_forces(d * facets(f, k) + c) += share * lc.direction(c);
  }
  const std::string where = mesh.source.empty() ? std::string("the mesh") : mesh.source;
  if (loaded == 0) throw InvalidArgument(where + " has no flat top boundary to load");
  if (lc.fixed_nodes.empty()) throw InvalidArgument(where + " has no bottom boundary to clamp");
  return lc;
}

void apply(const LoadCase& load, model::Problem& problem) {
  if (load.nodal_forces.size() != problem.model->dof_count())
    throw InvalidArgument("load case and problem belong to different meshes");
  model::fix_nodes(problem, load.fixed_nodes);
  problem.external_force = load.nodal_forces;
  model::zero_fixed_forces(problem);
}

double mean_top_displacement(const LoadCase& load, const model::Problem& problem, const VecX& positions) {
  const int d = problem.model->dim();
  const VecX u = positions - problem.model->rest_positions();
  double sum = 0.0;
  for (int node : load.top_nodes) sum += u.segment(d * node, d).dot(load.direction);
  return load.top_nodes.empty() ? 0.0 : sum / static_cast<double>(load.top_nodes.size());
}

double traction_for_strain(const mesh::Mesh& mesh, const std::vector<material::Material>& materials, LoadKind kind,
                           double strain) {
  return linear_response_for_strain(mesh, materials, kind, strain).traction_pa;
}

StrainResponse linear_response_for_strain(const mesh::Mesh& mesh, const std::vector<material::Material>& materials,
                                          LoadKind kind, double strain) {
  return std::move(linear_responses_for_strain(mesh, materials, {kind}, strain).front());
}

std::vector<StrainResponse> linear_responses_for_strain(const mesh::Mesh& mesh,
                                                        const std::vector<material::Material>& materials,
                                                        const std::vector<LoadKind>& kinds, double strain) {
  if (!(strain > 0.0) || !std::isfinite(strain)) throw InvalidArgument("the strain must be a positive number");
  model::Problem problem = model::make_problem(fem::linear_model(mesh, materials));
  std::vector<LoadCase> units;
  std::vector<VecX> forces;
  for (LoadKind kind : kinds) {
    units.push_back(make_load_case(mesh, kind, 1.0, materials.at(0).thickness));
    // Every kind clamps the same bottom nodes (make_load_case), so one factorisation serves them all.
    if (units.back().fixed_nodes != units.front().fixed_nodes)
      throw InvalidArgument("linear_responses_for_strain: load cases with different supports");
    forces.push_back(units.back().nodal_forces);
  }
  if (!units.empty()) model::fix_nodes(problem, units.front().fixed_nodes);
  for (VecX& f : forces) model::zero_fixed_forces(problem.fixed_dofs, f);
  std::vector<solve::StaticResult> fem = solve::linear_statics(problem, forces);
  std::vector<StrainResponse> out;
  const VecX& rest = problem.model->rest_positions();
  for (size_t k = 0; k < kinds.size(); ++k) {
    StrainResponse r;
    r.fem = std::move(fem[k]);
    solve::require_converged(r.fem.report);
    const double u = mean_top_displacement(units[k], problem, r.fem.positions);
    if (!(u > 0.0)) throw SolverFailure("the unit load produced no displacement along the load direction");
    const double t = strain * units[k].height / u;
    r.traction_pa = t;
    r.fem.positions = rest + t * (r.fem.positions - rest);
    solve::SolveReport& rep = r.fem.report;
    rep.residual *= t;
    rep.reference_force *= t;
    for (double& h : rep.residual_history) h *= t;
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace hooke::experiments
