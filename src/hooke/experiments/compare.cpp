#include <algorithm>
#include <cmath>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/core/error.hpp>
#include <hooke/experiments/compare.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/interpolate.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/solve/strain_response.hpp>

namespace hooke::experiments {
namespace {

VecX rest_of(const mesh::Mesh& m) { return Eigen::Map<const VecX>(m.nodes.data(), m.nodes.size()); }

// Comparisons need the equilibria and their stability, not the smallest eigenvalue's value (minutes of shifted
// factorisations on a scan's 300 000 tets). Newton keeps its factorisation while it reduces the residual fourfold
// (modified Newton: the same equilibrium to the tolerance; the femur's certificate 46 -> 31 s).
solve::StaticOptions statics(int load_steps = solve::StaticOptions{}.initial_load_steps) {
  solve::StaticOptions o;
  o.ramp_prescribed = true;  // displacement control: the press or pull reached in load steps
  o.estimate_min_eigenvalue = false;
  o.newton.reuse_factorization = true;
  o.newton.reuse_krylov_iterations = 20;
  o.initial_load_steps = load_steps;
  return o;
}

// An equilibrium with the force on the top nodes there.
struct Loaded {
  solve::StaticResult result;
  VecX reaction;
};

// The FEM reference under `load` (linear: one linear solve; otherwise Newton with the stability check).
Loaded solve_fem(const mesh::Mesh& mesh, const std::vector<material::Material>& materials, material::Law law,
                 const model::LoadCase& load) {
  model::Problem problem = model::make_problem(fem::elastic_model(mesh, materials, law));
  apply(load, problem);
  Loaded out{
      law == material::Law::kLinear ? solve::linear_static(problem) : solve::static_equilibrium(problem, statics()),
      {}};
  out.reaction = model::top_reaction(load, problem, out.result.positions);
  return out;
}

Loaded solve_springs(const mesh::Mesh& mesh, const calibrate::SpringModel& springs, const model::LoadCase& load,
                     int load_steps) {
  model::Problem problem = model::make_problem(calibrate::make_model(mesh, springs));
  apply(load, problem);
  Loaded out{solve::static_equilibrium(problem, statics(load_steps)), {}};
  out.reaction = model::top_reaction(load, problem, out.result.positions);
  return out;
}

// Relative error of a model's top force against the reference's: |r - r_ref| / |r_ref| (0 when both vanish).
double relative_force_error(const VecX& r, const VecX& r_ref) {
  const double scale = r_ref.norm();
  return scale > 0.0 ? (r - r_ref).norm() / scale : (r - r_ref).norm();
}

// Node errors of c.spring_positions against c.fem_positions; `rest` are the spring model's rest positions.
void measure(Comparison& c, const VecX& rest, int d) {
  const Eigen::Index n = c.spring_positions.size() / d;
  c.node_error.resize(n);
  for (Eigen::Index i = 0; i < n; ++i)
    c.node_error(i) = (c.spring_positions.segment(d * i, d) - c.fem_positions.segment(d * i, d)).norm();
  c.max_error = c.node_error.maxCoeff();
  c.mean_error = c.node_error.mean();
  const double reference = (c.fem_positions - rest).norm();
  c.relative_l2 = reference > 0.0 ? (c.spring_positions - c.fem_positions).norm() / reference : 0.0;
  if (c.fem_reaction.size() > 0 && c.spring_reaction.size() == c.fem_reaction.size())
    c.reaction_error = relative_force_error(c.spring_reaction, c.fem_reaction);
}

// The load case of `kind` on `mesh` under displacement control at o.strain (> 0).
model::LoadCase displacement_case(const mesh::Mesh& mesh, model::LoadKind kind, double thickness,
                                  const CompareOptions& o) {
  if (!(o.strain > 0.0) || !std::isfinite(o.strain))
    throw InvalidArgument("displacement control needs a strain > 0 (the top moved by strain x height)");
  model::LoadCase load = model::make_displacement_case(mesh, kind, 0.0, thickness);
  load.displacement = o.strain * load.height;
  return load;
}

double traction_of(const mesh::Mesh& mesh, const std::vector<material::Material>& materials, const CompareOptions& o) {
  if (o.strain != 0.0) return solve::traction_for_strain(mesh, materials, o.load, o.strain);  // refuses <= 0, NaN
  if (!std::isfinite(o.traction_pa)) throw InvalidArgument("the traction must be a finite number of pascals");
  return o.traction_pa;
}

// The load cases of `kinds` (o.load is not used) on `mesh` (thickness from the first material) and the FEM
// references under them. At a strain with the linear reference, the solve that finds each traction is the reference,
// one factorisation for all the kinds (linear_responses_for_strain).
std::vector<std::pair<model::LoadCase, Loaded>> loaded_references(const mesh::Mesh& mesh,
                                                                  const std::vector<material::Material>& materials,
                                                                  const std::vector<model::LoadKind>& kinds,
                                                                  const CompareOptions& o) {
  const double thickness = materials.at(0).thickness;
  std::vector<std::pair<model::LoadCase, Loaded>> out;
  if (o.control == model::LoadControl::kDisplacement) {
    for (model::LoadKind kind : kinds) {
      model::LoadCase load = displacement_case(mesh, kind, thickness, o);
      Loaded fem = solve_fem(mesh, materials, o.reference, load);
      out.emplace_back(std::move(load), std::move(fem));
    }
    return out;
  }
  if (o.strain != 0.0 && o.reference == material::Law::kLinear) {
    std::vector<solve::StrainResponse> r =
        solve::linear_responses_for_strain(mesh, materials, kinds, o.strain);  // refuses <= 0
    for (size_t k = 0; k < kinds.size(); ++k) {
      model::LoadCase load = model::make_load_case(mesh, kinds[k], r[k].traction_pa, thickness);
      VecX reaction = VecX::Zero(mesh.dim());  // the linear FEM in equilibrium carries the applied load
      for (int node : load.top_nodes) reaction += load.nodal_forces.segment(mesh.dim() * node, mesh.dim());
      out.emplace_back(std::move(load), Loaded{std::move(r[k].fem), std::move(reaction)});
    }
    return out;
  }
  for (model::LoadKind kind : kinds) {
    CompareOptions one = o;
    one.load = kind;
    model::LoadCase load = model::make_load_case(mesh, kind, traction_of(mesh, materials, one), thickness);
    Loaded fem = solve_fem(mesh, materials, o.reference, load);
    out.emplace_back(std::move(load), std::move(fem));
  }
  return out;
}

// The load case of `o` on `mesh` and the FEM reference under it.
std::pair<model::LoadCase, Loaded> loaded_reference(const mesh::Mesh& mesh,
                                                    const std::vector<material::Material>& materials,
                                                    const CompareOptions& o) {
  return std::move(loaded_references(mesh, materials, {o.load}, o).front());
}

}  // namespace

std::vector<Comparison> compare_models(const mesh::Mesh& mesh, const std::vector<material::Material>& materials,
                                       const std::vector<calibrate::SpringModel>& models,
                                       const CompareOptions& options) {
  const auto [load, fem] = loaded_reference(mesh, materials, options);
  std::vector<Comparison> out;
  for (const auto& springs : models) {
    Comparison c;
    c.load = load;
    const Loaded msm = solve_springs(mesh, springs, c.load, options.load_steps);
    c.springs = springs;
    c.fem_mesh = mesh;
    c.fem_positions = fem.result.positions;
    c.fem_mesh_positions = fem.result.positions;
    c.spring_positions = msm.result.positions;
    c.fem_report = fem.result.report;
    c.spring_report = msm.result.report;
    c.fem_reaction = fem.reaction;
    c.spring_reaction = msm.reaction;
    measure(c, rest_of(mesh), mesh.dim());
    out.push_back(std::move(c));
  }
  return out;
}

Comparison compare_model(const mesh::Mesh& mesh, const std::vector<material::Material>& materials,
                         const calibrate::SpringModel& springs, const CompareOptions& options) {
  return std::move(compare_models(mesh, materials, {springs}, options).front());
}

Comparison compare(const mesh::Mesh& mesh, const std::vector<material::Material>& materials,
                   const CompareOptions& options) {
  return compare_model(mesh, materials, calibrate::calibrate(mesh, materials, options.method), options);
}

Comparison compare_across(const mesh::Mesh& coarse, const mesh::Mesh& fine, const material::Material& material,
                          const CompareOptions& options) {
  Comparison c;
  model::LoadCase fine_load;
  if (options.control == model::LoadControl::kDisplacement) {
    c.load = displacement_case(coarse, options.load, material.thickness, options);
    fine_load = displacement_case(fine, options.load, material.thickness, options);
  } else {
    const double traction = traction_of(fine, {material}, options);
    c.load = model::make_load_case(coarse, options.load, traction, material.thickness);
    fine_load = model::make_load_case(fine, options.load, traction, material.thickness);
  }
  const Loaded fem = solve_fem(fine, {material}, options.reference, fine_load);
  c.springs = calibrate::calibrate(coarse, {material}, options.method);
  const Loaded msm = solve_springs(coarse, c.springs, c.load, options.load_steps);
  const int d = coarse.dim();
  c.fem_mesh_positions = fem.result.positions;
  c.fem_mesh = fine;
  const RowMatX at_coarse =
      mesh::interpolate_nodal(fine, mesh::positions_as_rows(fem.result.positions, d), coarse.nodes);
  c.fem_positions = Eigen::Map<const VecX>(at_coarse.data(), at_coarse.size());
  c.spring_positions = msm.result.positions;
  c.fem_report = fem.result.report;
  c.spring_report = msm.result.report;
  c.fem_reaction = fem.reaction;
  c.spring_reaction = msm.reaction;
  measure(c, rest_of(coarse), d);
  return c;
}

namespace {

// A springs or file model: the only kinds compared node for node on their own mesh. @throws InvalidArgument
void require_node_model(const calibrate::CalibratedModel& model) {
  if (model.surface) throw InvalidArgument("compare: a surface model is compared on its radial tets");
  if (calibrate::model_kind(model) == calibrate::ModelKind::kFem)
    throw InvalidArgument("compare: the model is the FEM model itself");
}

}  // namespace

std::vector<Reference> fem_references(const calibrate::CalibratedModel& model,
                                      const std::vector<model::LoadKind>& kinds, const CompareOptions& options) {
  require_node_model(model);
  std::vector<Reference> out;
  for (auto& [load, fem] : loaded_references(model.mesh, calibrate::element_materials(model), kinds, options))
    out.push_back({std::move(load), std::move(fem.result), std::move(fem.reaction)});
  return out;
}

std::vector<Comparison> compare_to_references(const calibrate::CalibratedModel& model,
                                              const std::vector<Reference>& references, const CompareOptions& options,
                                              const std::vector<VecX>& starts) {
  require_node_model(model);
  if (!starts.empty() && starts.size() != references.size())
    throw InvalidArgument("compare: " + std::to_string(starts.size()) + " initial guesses for " +
                          std::to_string(references.size()) + " load cases");
  const calibrate::BuiltModel built = calibrate::build_model(model);
  const VecX rest = built.model->rest_positions();
  std::vector<solve::StaticResult> msm;
  std::vector<model::Problem> problems;
  const bool same_supports = std::all_of(references.begin(), references.end(), [&](const Reference& r) {
    return r.load.control == model::LoadControl::kTraction && r.load.fixed_nodes == references.front().load.fixed_nodes;
  });
  if (same_supports) {
    // Every load case clamps the same nodes (make_load_case): one problem, its loads solved in turn by one solver.
    model::Problem& problem = problems.emplace_back(model::make_problem(built.model));
    std::vector<VecX> forces;
    for (const Reference& r : references) {
      apply(r.load, problem);
      forces.push_back(problem.external_force);
    }
    msm = solve::static_equilibria(problem, forces, statics(options.load_steps));
  } else {
    // Each case holds its own top positions (displacement control): one problem per case.
    for (size_t k = 0; k < references.size(); ++k) {
      model::Problem& problem = problems.emplace_back(model::make_problem(built.model));
      apply(references[k].load, problem);
      solve::StaticOptions o = statics(options.load_steps);
      if (!starts.empty()) o.start = starts[k];
      msm.push_back(solve::static_equilibrium(problem, o));
    }
  }
  std::vector<Comparison> out;
  for (size_t k = 0; k < references.size(); ++k) {
    Comparison c;
    c.springs = model.springs;
    c.load = references[k].load;
    c.fem_positions = c.fem_mesh_positions = references[k].fem.positions;
    c.fem_mesh = model.mesh;
    c.spring_positions = std::move(msm[k].positions);
    c.fem_report = references[k].fem.report;
    c.spring_report = std::move(msm[k].report);
    c.fem_reaction = references[k].reaction;
    c.spring_reaction = model::top_reaction(c.load, problems[std::min(k, problems.size() - 1)], c.spring_positions);
    measure(c, rest, model.mesh.dim());
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<Comparison> compare_calibrated_cases(const calibrate::CalibratedModel& model,
                                                 const std::vector<model::LoadKind>& kinds,
                                                 const CompareOptions& options, int layers) {
  if (!model.surface) return compare_to_references(model, fem_references(model, kinds, options), options);
  const calibrate::BuiltModel built = calibrate::build_model(model);
  const VecX rest = built.model->rest_positions();
  std::vector<Comparison> out;
  // Arnab & Raja's surface model against the FEM of the volume it encloses, tetrahedralised radially.
  const mesh::Mesh& surface = model.mesh;
  const mesh::Mesh tets = mesh::tetrahedralise_radially(surface, model.surface->centre, layers);
  const int n = surface.node_count(), offset = 1 + (layers - 1) * n;  // tet node of surface node i: offset + i
  auto references = loaded_references(tets, {model.material}, kinds, options);
  for (auto& [fine, fem_loaded] : references) {
    Comparison c;
    c.springs = model.springs;
    model::Problem problem = model::make_problem(built.model);
    problem.external_force = fine.nodal_forces.segment(3 * offset, 3 * n);
    solve::StaticResult& fem = fem_loaded.result;
    c.load = fine;
    c.load.fixed_nodes.clear();
    c.load.top_nodes.clear();
    for (int i : fine.fixed_nodes) {
      if (i < offset) throw InvalidArgument("compare_surface: a clamped node lies inside the body");
      c.load.fixed_nodes.push_back(i - offset);
    }
    for (int i : fine.top_nodes)
      if (i >= offset) c.load.top_nodes.push_back(i - offset);
    c.load.nodal_forces = problem.external_force;
    apply(c.load, problem);
    if (built.volume_penalty && c.load.top_nodes.size() > 0) {
      // The interaction of Eq. 4 at the centre of the loaded face, along the load (so one problem per load case).
      Vec3 centre = Vec3::Zero();
      for (int i : c.load.top_nodes) centre += surface.nodes.row(i).transpose() / c.load.top_nodes.size();
      problem.interaction = model::Interaction{centre, Vec3(c.load.direction), mesh::bounding_box_diagonal(surface)};
    }
    solve::StaticOptions surface_statics = statics(options.load_steps);
    surface_statics.newton.max_iterations = 100;
    const solve::StaticResult msm = solve::static_equilibrium(problem, surface_statics);
    c.fem_mesh_positions = fem.positions;
    c.fem_mesh = tets;
    c.fem_positions = fem.positions.segment(3 * offset, 3 * n);
    c.spring_positions = msm.positions;
    c.fem_report = std::move(fem.report);
    c.spring_report = msm.report;
    c.fem_reaction = std::move(fem_loaded.reaction);
    c.spring_reaction = model::top_reaction(c.load, problem, c.spring_positions);
    measure(c, rest, 3);
    out.push_back(std::move(c));
  }
  return out;
}

Comparison compare_calibrated(const calibrate::CalibratedModel& model, const CompareOptions& options, int layers) {
  return std::move(compare_calibrated_cases(model, {options.load}, options, layers).front());
}

Comparison compare_surface(const mesh::Mesh& surface, const material::Material& material,
                           const calibrate::SurfaceOptions& surface_options, const CompareOptions& options,
                           int layers) {
  calibrate::ModelOptions mo;
  mo.method = calibrate::model_kind_name(calibrate::ModelKind::kSurface);
  mo.density = surface_options.density;
  mo.surface = surface_options;
  return compare_calibrated(calibrate::calibrate_model(surface, material, mo), options, layers);
}

}  // namespace hooke::experiments
