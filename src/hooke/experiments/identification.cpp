#include <algorithm>
#include <chrono>
#include <cmath>
#include <hooke/calibrate/method.hpp>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/sparse_cholesky.hpp>
#include <hooke/experiments/identification.hpp>
#include <hooke/experiments/term_law_fit.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/identify/positions_objective.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/model/free_map.hpp>
#include <hooke/model/mass.hpp>
#include <hooke/model/problem.hpp>
#include <hooke/model/support.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <nlohmann/json.hpp>
#include <random>

namespace hooke::experiments {
namespace {

constexpr const char* kAxes = "xyz";
constexpr double kEndQuarter = 0.25;  // the reference loads' supports and loaded facets: a quarter of the extent

// The supported and loaded facets of one axis: outward normal within 60 degrees of -a (+a), centroid in the lowest
// (highest) quarter of the extent along a.
struct AxisEnds {
  int axis = 0;
  double extent = 0.0;
  std::vector<char> fixed_dofs;
  std::vector<int> loaded;        // facets
  std::vector<int> loaded_nodes;  // their nodes, sorted
};

AxisEnds axis_ends(const mesh::Mesh& mesh, const model::BoundaryFacets& b, int axis) {
  AxisEnds e;
  e.axis = axis;
  e.extent = mesh.nodes.col(axis).maxCoeff() - mesh.nodes.col(axis).minCoeff();
  const int d = mesh.dim();
  e.fixed_dofs.assign(static_cast<std::size_t>(d * mesh.node_count()), 0);
  const std::vector<int> supports = model::facing_end_facets(mesh, b, axis, model::End::kLow, kEndQuarter);
  for (int f : supports)
    for (int a = 0; a < b.facets.cols(); ++a)
      for (int k = 0; k < d; ++k) e.fixed_dofs[static_cast<std::size_t>(d * b.facets(f, a) + k)] = 1;
  e.loaded = model::facing_end_facets(mesh, b, axis, model::End::kHigh, kEndQuarter);
  for (int f : e.loaded)
    for (int a = 0; a < b.facets.cols(); ++a) e.loaded_nodes.push_back(b.facets(f, a));
  std::sort(e.loaded_nodes.begin(), e.loaded_nodes.end());
  e.loaded_nodes.erase(std::unique(e.loaded_nodes.begin(), e.loaded_nodes.end()), e.loaded_nodes.end());
  if (supports.empty() || e.loaded.empty())
    throw InvalidArgument(std::string("reference loads: ") + mesh.source + " has no boundary facets facing the " +
                          (supports.empty() ? "low" : "high") + " end of the " + kAxes[axis] + " axis");
  return e;
}

// Consistent nodal forces of a traction field t(centroid) (Pa) on the given facets: t x measure (x thickness in 2D)
// shared equally by the facet's nodes.
template <class Traction>
VecX traction_forces(const mesh::Mesh& mesh, const model::BoundaryFacets& b, const std::vector<int>& facets,
                     double thickness, Traction traction) {
  const int d = mesh.dim();
  VecX f = VecX::Zero(d * mesh.node_count());
  const double scale = d == 2 ? thickness : 1.0;
  for (int facet : facets) {
    const VecX t = traction(b.centroids.row(facet).transpose());
    const double share = scale * b.measures(facet) / static_cast<double>(b.facets.cols());
    for (int a = 0; a < b.facets.cols(); ++a) f.segment(d * b.facets(facet, a), d) += share * t;
  }
  return f;
}

// A case before solving: its supports, its forces at a unit traction scale and, for displacement control, its
// loaded nodes' move at unit scale (the traction's direction field at each node).
struct PendingCase {
  std::string name;
  const AxisEnds* ends;
  VecX unit_force;
  bool held_out;
  VecX unit_move;  // flat, nonzero on the loaded facets' nodes
};

// The loaded facets' nodes moved by field(node position), flat.
template <class Field>
VecX facet_node_moves(const mesh::Mesh& mesh, const model::BoundaryFacets& b, const std::vector<int>& facets,
                      Field field) {
  const int d = mesh.dim();
  VecX u = VecX::Zero(d * mesh.node_count());
  for (int facet : facets)
    for (int a = 0; a < b.facets.cols(); ++a) {
      const int n = b.facets(facet, a);
      u.segment(d * n, d) = field(VecX(mesh.nodes.row(n).transpose()));
    }
  return u;
}

std::vector<PendingCase> pending_cases(const mesh::Mesh& mesh, const model::BoundaryFacets& b,
                                       const std::vector<AxisEnds>& ends, const ReferenceLoads& loads,
                                       double thickness) {
  const int d = mesh.dim();
  std::vector<PendingCase> out;
  for (const AxisEnds& e : ends) {
    const std::string end = std::string(" on the +") + kAxes[e.axis] + " end";
    for (int sign : {+1, -1}) {
      VecX dir = VecX::Zero(d);
      dir(e.axis) = sign;
      const auto field = [&](const VecX&) { return dir; };
      out.push_back({(sign > 0 ? "stretch" : "compress") + end, &e,
                     traction_forces(mesh, b, e.loaded, thickness, field), false,
                     facet_node_moves(mesh, b, e.loaded, field)});
    }
    for (int other = 0; other < d; ++other) {
      if (other == e.axis) continue;
      VecX dir = VecX::Zero(d);
      dir(other) = 1.0;
      const auto field = [&](const VecX&) { return dir; };
      out.push_back({std::string("shear +") + kAxes[other] + end, &e,
                     traction_forces(mesh, b, e.loaded, thickness, field), false,
                     facet_node_moves(mesh, b, e.loaded, field)});
    }
  }
  std::mt19937 rng(loads.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  VecX centre = VecX(mesh.nodes.colwise().mean().transpose());
  for (int r = 0; r < loads.held_out; ++r) {
    const AxisEnds& e = ends[static_cast<std::size_t>(r % d)];
    VecX dir(d), slope(d);
    for (int k = 0; k < d; ++k) {
      dir(k) = normal(rng);
      slope(k) = uniform(rng);
    }
    dir.normalize();
    const double size = std::max(e.extent, 1e-300);
    const auto field = [&](const VecX& c) { return VecX(dir * (1.0 + 0.5 * slope.dot(c - centre) / size)); };
    out.push_back({"random " + std::to_string(r + 1) + " on the +" + kAxes[e.axis] + " end", &e,
                   traction_forces(mesh, b, e.loaded, thickness, field), true,
                   facet_node_moves(mesh, b, e.loaded, field)});
  }
  return out;
}

// A case under displacement control: the supports clamped, the loaded nodes held at rest + strain x extent x the
// unit move (ramped from rest with the load factor), the FEM's equilibrium and the force holding each loaded node.
identify::ReferenceCase displaced_case(const std::shared_ptr<model::Model>& fem, const PendingCase& p, const VecX& rest,
                                       double strain, material::Law law) {
  const int d = fem->dim();
  identify::ReferenceCase c{p.name,
                            rest,
                            VecX::Zero(rest.size()),
                            p.ends->fixed_dofs,
                            p.held_out,
                            std::vector<char>(static_cast<std::size_t>(rest.size()), 0)};
  for (int node : p.ends->loaded_nodes)
    for (int k = 0; k < d; ++k) {
      const auto dof = static_cast<std::size_t>(d * node + k);
      if (!c.fixed_dofs[dof]) c.prescribed_dofs[dof] = 1;
    }
  model::Problem problem = model::make_problem(fem);
  problem.fixed_dofs = identify::held_dofs(c);
  problem.prescribed_positions = rest + strain * p.ends->extent * p.unit_move;
  solve::StaticOptions statics;
  statics.ramp_prescribed = true;
  const solve::StaticResult r = solve::static_equilibrium(problem, statics);
  if (r.report.status != solve::SolveStatus::kConverged)
    throw SolverFailure("reference case '" + c.name + "' (" + std::string(material::law_name(law)) +
                        " FEM, displacement control): " + r.report.message);
  c.positions = r.positions;
  c.external_force = identify::prescribed_part(c, fem->gradient(r.positions));
  return c;
}

double rms(const std::vector<double>& errors, const std::vector<char>& held_out, bool which) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t c = 0; c < errors.size(); ++c)
    if (static_cast<bool>(held_out[c]) == which) {
      sum += errors[c] * errors[c];
      ++n;
    }
  return n ? std::sqrt(sum / n) : 0.0;
}

}  // namespace

std::vector<identify::ReferenceCase> fem_reference_cases(const mesh::Mesh& mesh, const material::Material& material,
                                                         const ReferenceLoads& loads) {
  if (mesh.kind != mesh::ElementKind::kTet && mesh.kind != mesh::ElementKind::kTriangle)
    throw InvalidArgument("reference loads need a tet or triangle mesh");
  if (!(loads.strain > 0.0) || !std::isfinite(loads.strain))
    throw InvalidArgument("reference loads: the strain must be positive");
  const int d = mesh.dim();
  const model::BoundaryFacets b = model::boundary_facets_with_geometry(mesh);
  std::vector<AxisEnds> ends;
  for (int a = 0; a < d; ++a) ends.push_back(axis_ends(mesh, b, a));
  const std::vector<PendingCase> pending = pending_cases(mesh, b, ends, loads, material.thickness);

  const VecX rest = mesh::flat_positions(mesh);
  auto linear_model = fem::linear_model(mesh, {material});
  const SparseMatrix stiffness = linear_model->hessian(rest);
  std::shared_ptr<model::Model> nonlinear_model;
  if (material.law != material::Law::kLinear) nonlinear_model = fem::elastic_model(mesh, {material});

  std::vector<identify::ReferenceCase> out;
  if (loads.control == model::LoadControl::kDisplacement) {
    const std::shared_ptr<model::Model> fem = nonlinear_model ? nonlinear_model : linear_model;
    for (const PendingCase& p : pending) out.push_back(displaced_case(fem, p, rest, loads.strain, material.law));
    return out;
  }
  for (const AxisEnds& e : ends) {
    std::vector<int> free;
    for (int dof = 0; dof < static_cast<int>(rest.size()); ++dof)
      if (!e.fixed_dofs[static_cast<std::size_t>(dof)]) free.push_back(dof);
    const model::FreeMap map(free, static_cast<int>(rest.size()));
    SparseCholesky cholesky;
    if (!cholesky.factorize(map.restrict(stiffness)))
      throw SolverFailure("reference loads: the FEM stiffness with the " + std::string(1, kAxes[e.axis]) +
                          " supports is singular (is the mesh connected?)");
    for (const PendingCase& p : pending) {
      if (p.ends != &e) continue;
      const VecX u_free = cholesky.solve(map.restrict(p.unit_force));
      VecX u = VecX::Zero(rest.size());
      double largest = 0.0;
      for (int i = 0; i < map.size(); ++i) u(free[static_cast<std::size_t>(i)]) = u_free(i);
      for (int n = 0; n < mesh.node_count(); ++n) largest = std::max(largest, u.segment(d * n, d).norm());
      const double scale = loads.strain * e.extent / largest;
      identify::ReferenceCase c{p.name, rest + scale * u, scale * p.unit_force, e.fixed_dofs, p.held_out, {}};
      if (nonlinear_model) {
        const solve::StaticResult r = identify::reference_equilibrium(nonlinear_model, c, {}, c.positions);
        if (r.report.status != solve::SolveStatus::kConverged)
          throw SolverFailure("reference case '" + c.name + "' (" + std::string(material::law_name(material.law)) +
                              " FEM): " + r.report.message);
        c.positions = r.positions;
      }
      model::zero_fixed_forces(c.fixed_dofs, c.external_force);
      out.push_back(std::move(c));
    }
  }
  return out;
}

IdentificationStudy identification_study(const mesh::Mesh& mesh, const material::Material& material,
                                         const std::vector<identify::ReferenceCase>& cases,
                                         const identify::IdentifyOptions& options, const std::string& analytic_method,
                                         double strain_range) {
  IdentificationStudy s;
  calibrate::SpringModel analytic =
      calibrate::calibrate(mesh, {material}, calibrate::method_from_name(analytic_method));
  if (strain_range > 0.0 && material.law != material::Law::kLinear) {
    calibrate::ModelOptions mo;
    mo.method = analytic_method;
    material::Material linear = material;
    linear.law = material::Law::kLinear;
    TermLawFitOptions fo;
    fo.law = material.law;
    fo.strain_range = strain_range;
    analytic = with_fitted_law(calibrate::calibrate_model(mesh, linear, mo), fo).springs;
  }
  identify::IdentifyOptions with_start = options;
  if (!with_start.start_model) with_start.start_model = analytic;
  s.identification = identify::identify(mesh, cases, with_start);
  s.analytic_method = analytic_method;
  const auto t0 = std::chrono::steady_clock::now();
  s.identified_errors =
      identify::position_errors(mesh, s.identification.springs, cases, options.statics, &s.identified_force_errors);
  s.analytic_errors = identify::position_errors(mesh, analytic, cases, options.statics, &s.analytic_force_errors);
  std::vector<identify::ReferenceCase> training;
  for (const identify::ReferenceCase* c : identify::training_cases(cases)) training.push_back(*c);
  identify::ParameterLayout layout = identify::parameter_layout(
      mesh, analytic.volume_tets.rows() ? identify::Parameters::kSpringsVolume : identify::Parameters::kSprings);
  layout.spring_exponent = analytic.spring_exponent;
  layout.volume_exponent = analytic.volume_exponent;
  s.analytic_force_residual = identify::force_residual(layout, identify::parameters_of(layout, analytic), training);
  s.evaluation_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const auto& c : cases) {
    s.case_names.push_back(c.name);
    s.held_out.push_back(c.held_out ? 1 : 0);
  }
  s.training_error = rms(s.identified_errors, s.held_out, false);
  s.held_out_error = rms(s.identified_errors, s.held_out, true);
  s.analytic_training_error = rms(s.analytic_errors, s.held_out, false);
  s.analytic_held_out_error = rms(s.analytic_errors, s.held_out, true);
  return s;
}

identify::Parameters default_parameters(const mesh::Mesh& mesh) {
  return mesh.kind == mesh::ElementKind::kTet ? identify::Parameters::kSpringsVolume : identify::Parameters::kSprings;
}

identify::IdentifyOptions identify_options(const NamedIdentifyOptions& named, const mesh::Mesh& mesh) {
  identify::IdentifyOptions options;
  options.parameters =
      named.parameters == "auto" ? default_parameters(mesh) : identify::parameters_from_name(named.parameters);
  options.objective = identify::objective_from_name(named.objective);
  options.regularization = named.regularization;
  options.stiffness_floor = named.stiffness_floor;
  options.position_iterations = named.iterations;
  options.least_squares.tolerance = named.tolerance;
  options.negative_volume = named.negative_volume;
  identify::validate_options(options);
  return options;
}

std::string default_analytic_method(const mesh::Mesh& mesh) {
  return mesh.kind == mesh::ElementKind::kTet ? "any-nu-tet" : "any-nu-triangle";
}

calibrate::CalibratedModel identified_model(const mesh::Mesh& mesh, const material::Material& material, double density,
                                            const IdentificationStudy& study,
                                            const identify::IdentifyOptions& options) {
  calibrate::CalibratedModel m;
  m.method = "identified";
  const auto training = std::count(study.held_out.begin(), study.held_out.end(), 0);
  m.equation =
      std::string("Lloyd et al. 2007, ") +
      (options.parameters == identify::Parameters::kScale
           ? "Eq. 1 (positions) with one factor c = " + std::to_string(study.identification.report.scale_factor) +
                 " on " + study.analytic_method
           : (options.objective == identify::Objective::kForces ? "Eq. 2 (forces)" : "Eq. 1 (positions)") +
                 std::string(", parameters ") + std::string(identify::parameters_name(options.parameters))) +
      ", identified from " + std::to_string(training) + " reference cases";
  m.mesh = mesh;
  m.material = material;
  m.density = density;
  m.masses = model::lumped_masses(mesh, density, material.thickness);
  m.springs = study.identification.springs;
  calibrate::validate_model(m, "the identified model");
  return m;
}

std::string identification_report_json(const IdentificationStudy& study, const identify::IdentifyOptions& options) {
  const identify::IdentifyReport& r = study.identification.report;
  nlohmann::json cases = nlohmann::json::array();
  for (std::size_t c = 0; c < study.case_names.size(); ++c)
    cases.push_back({{"name", study.case_names[c]},
                     {"held_out", static_cast<bool>(study.held_out[c])},
                     {"identified_relative_l2", study.identified_errors[c]},
                     {"analytic_relative_l2", study.analytic_errors[c]},
                     {"identified_force_error", study.identified_force_errors[c]},
                     {"analytic_force_error", study.analytic_force_errors[c]}});
  const nlohmann::json j = {{"objective", identify::objective_name(options.objective)},
                            {"parameters", identify::parameters_name(options.parameters)},
                            {"regularization", options.regularization},
                            {"stiffness_floor", options.stiffness_floor},
                            {"negative_volume", options.negative_volume},
                            {"tolerance", options.least_squares.tolerance},
                            {"analytic_method", study.analytic_method},
                            {"cases", cases},
                            {"training_relative_l2_rms", study.training_error},
                            {"held_out_relative_l2_rms", study.held_out_error},
                            {"analytic_training_relative_l2_rms", study.analytic_training_error},
                            {"analytic_held_out_relative_l2_rms", study.analytic_held_out_error},
                            {"force_residual", r.force_residual},
                            {"analytic_force_residual", study.analytic_force_residual},
                            {"least_squares",
                             {{"iterations", r.least_squares.iterations},
                              {"cg_iterations", r.least_squares.cg_iterations},
                              {"products", r.least_squares.products},
                              {"projected_gradient", r.least_squares.projected_gradient},
                              {"at_bound", r.least_squares.at_bound},
                              {"converged", r.least_squares.converged}}},
                            {"positions",
                             {{"iterations", r.position_iterations},
                              {"static_solves", r.static_solves},
                              {"eq2_objective", r.eq2_positions_objective},
                              {"start_model_objective", r.start_model_objective},
                              {"started_from_model", r.started_from_model},
                              {"history", r.position_history}}},
                            {"clamped_rest_lengths", r.clamped_rest_lengths},
                            {"springs", study.identification.layout.spring_count()},
                            {"volume_terms", study.identification.layout.volume_count()},
                            {"min_stiffness_n_per_m", r.min_stiffness},
                            {"scale_factor", r.scale_factor},
                            {"max_stiffness_n_per_m", r.max_stiffness},
                            {"identification_seconds", r.seconds},
                            {"evaluation_seconds", study.evaluation_seconds}};
  return j.dump(2) + "\n";
}

}  // namespace hooke::experiments
