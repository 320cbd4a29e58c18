#pragma once
/// A spring model against the FEM reference on one load case (Lloyd et al. 2007, Sec. 5).
#include <hooke/calibrate/calibrated_model.hpp>
#include <hooke/calibrate/method.hpp>
#include <hooke/calibrate/surface_model.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <vector>

namespace hooke::experiments {

struct CompareOptions {
  calibrate::Method method = calibrate::Method::kLloydTet;  ///< how the springs are calibrated
  model::LoadKind load = model::LoadKind::kStretch;         ///< load case
  double traction_pa = 0.0;                                 ///< traction, Pa (ignored when strain != 0)
  /// != 0: the traction giving this mean linear-FEM strain (then it must be > 0); under displacement control the top
  /// moved by strain x height
  double strain = 0.0;
  /// traction (default) or displacement control; displacement control needs `strain` (> 0)
  model::LoadControl control = model::LoadControl::kTraction;
  material::Law reference = material::Law::kLinear;  ///< FEM reference law
  /// the model's static solve starts with this many equal load steps (halved where Newton fails; every accepted
  /// state checked for stability), default 4; certify uses 1 at its small strains
  int load_steps = solve::StaticOptions{}.initial_load_steps;
};

struct Comparison {
  model::LoadCase load;      ///< the boundary conditions the spring model saw
  VecX fem_positions;        ///< FEM equilibrium at the spring model's nodes, flat, m
  VecX fem_mesh_positions;   ///< FEM equilibrium on the reference mesh's own nodes, flat, m
  mesh::Mesh fem_mesh;       ///< the reference mesh (the model's own, a finer one, or the surface's tets)
  VecX spring_positions;     ///< spring-model equilibrium, flat, m
  VecX node_error;           ///< |x_spring - x_fem| per node, m
  double max_error = 0.0;    ///< m
  double mean_error = 0.0;   ///< m
  double relative_l2 = 0.0;  ///< ||x_spring - x_fem|| / ||x_fem - X|| over all (compared) nodes
  /// total force on the top nodes (model::top_reaction), N (dim): under displacement control what the instrument that
  /// moved them feels; under traction control the applied load once in equilibrium
  VecX fem_reaction, spring_reaction;
  double reaction_error = 0.0;  ///< |R_spring - R_fem| / |R_fem|
  solve::SolveReport fem_report, spring_report;
  calibrate::SpringModel springs;
};

/// Applies the same nodal forces and clamped nodes to the FEM reference and to the calibrated spring model,
/// solves both (linear FEM: one linear solve; otherwise Newton with the stability check) and measures the
/// Euclidean node distance. Both reports must be kConverged for the errors to mean anything: check them.
/// @param materials  one material, or one per element (the law is taken from options.reference)
Comparison compare(const mesh::Mesh& mesh, const std::vector<material::Material>& materials,
                   const CompareOptions& options);

/// The same with a given spring model on `mesh` (a variant no method names); options.method is ignored.
Comparison compare_model(const mesh::Mesh& mesh, const std::vector<material::Material>& materials,
                         const calibrate::SpringModel& springs, const CompareOptions& options);

/// The same for several spring models on `mesh` under one load case: the FEM reference (and the traction for
/// options.strain) is solved once. One Comparison per model, in order.
std::vector<Comparison> compare_models(const mesh::Mesh& mesh, const std::vector<material::Material>& materials,
                                       const std::vector<calibrate::SpringModel>& models,
                                       const CompareOptions& options);
/// A spring model on `coarse` against the FEM reference on `fine`, a finer mesh of the same object (Lloyd
/// Sec. 5.4): both carry the same traction (from options.strain on the fine linear FEM, else
/// options.traction_pa) on their own top boundaries; the FEM positions are interpolated at the coarse nodes.
/// @param material  one homogeneous material (law taken from options.reference)
/// @throws InvalidArgument if a coarse node lies outside the fine mesh
Comparison compare_across(const mesh::Mesh& coarse, const mesh::Mesh& fine, const material::Material& material,
                          const CompareOptions& options);

/// Arnab & Raja's surface model of the closed surface `surface` against the FEM of the volume inside it,
/// tetrahedralised radially from the surface model's centre (mesh::tetrahedralise_radially, `layers` layers; its
/// boundary nodes are the surface's nodes). The load case is built on the tet mesh (clamped bottom, traction on
/// the top facets); the surface model gets the same nodal forces and clamped nodes at its own nodes. Errors are
/// over the surface nodes; `springs` stays empty, fem_mesh_positions are on the tet mesh.
/// @param material  one homogeneous material (law taken from options.reference); options.method is ignored
Comparison compare_surface(const mesh::Mesh& surface, const material::Material& material,
                           const calibrate::SurfaceOptions& surface_options, const CompareOptions& options,
                           int layers = 4);

/// Any calibrated model (springs, volume terms, a surface model, or one read from a file) against the FEM of
/// its own mesh and material (model.material with the law options.reference) on one load case. A surface model
/// is compared as compare_surface does, on `layers` radial layers around model.surface->centre.
/// @throws InvalidArgument for the "fem" model (nothing to compare) or a model validate_model rejects
Comparison compare_calibrated(const calibrate::CalibratedModel& model, const CompareOptions& options, int layers = 4);

/// The FEM reference of one load case: the boundary conditions, the equilibrium and the force on the top there.
struct Reference {
  model::LoadCase load;
  solve::StaticResult fem;
  VecX reaction;  ///< model::top_reaction at fem.positions, N (dim)
};

/// The FEM references of a springs or file model (not "surface", not "fem") on each of `kinds` (options.load is not
/// used; options.reference is the law, options.control and options.strain the load), on model.mesh with
/// model.material, for compare_to_references. Check each fem.report.
/// @throws InvalidArgument for a surface or FEM model, or as compare_calibrated
std::vector<Reference> fem_references(const calibrate::CalibratedModel& model,
                                      const std::vector<model::LoadKind>& kinds, const CompareOptions& options);

/// A springs or file model against references made by fem_references on its mesh: one Comparison per reference, the
/// model's statics as compare_calibrated_cases solves them (options.load_steps; the other fields are not used).
/// @param starts  optional initial guesses, one per reference (flat positions, m; solve::StaticOptions::start),
///                e.g. the equilibria of a nearby model; used under displacement control
/// @throws InvalidArgument for a surface or FEM model, or a count of starts other than the references'
std::vector<Comparison> compare_to_references(const calibrate::CalibratedModel& model,
                                              const std::vector<Reference>& references, const CompareOptions& options,
                                              const std::vector<VecX>& starts = {});

/// compare_calibrated on each of `kinds` (options.load is not used): the FEM references from one factorisation at a
/// strain, and a spring or FEM-kind model's statics by static_equilibria (one stability test of the rest state and
/// one kept factorisation for all the loads). The same comparisons as separate calls, to Newton's tolerance.
std::vector<Comparison> compare_calibrated_cases(const calibrate::CalibratedModel& model,
                                                 const std::vector<model::LoadKind>& kinds,
                                                 const CompareOptions& options, int layers = 4);

}  // namespace hooke::experiments
