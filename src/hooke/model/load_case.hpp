#pragma once
/// The papers' load cases (Lloyd et al. 2007, Sec. 5): bottom clamped, a uniform dead traction on the top; and the
/// same cases under displacement control (the top moved rigidly, the reaction force measured), as a probe or an
/// instrument presses tissue.
#include <hooke/mesh/mesh.hpp>
#include <hooke/model/problem.hpp>
#include <string_view>
#include <vector>

namespace hooke::model {

/// Stable names: "stretch", "compress", "shear".
enum class LoadKind {
  kStretch,   ///< traction along +y (2D) / +z (3D) on the top boundary
  kCompress,  ///< traction along -y / -z
  kShear      ///< tangential traction along +x (2D) / +y (3D), as in Lloyd Sec. 5
};

LoadKind load_kind_from_name(std::string_view name);  ///< @throws InvalidArgument
std::string_view load_kind_name(LoadKind kind);

/// What the top boundary is given. Stable names: "traction", "displacement".
enum class LoadControl {
  kTraction,     ///< a dead traction on the top facets; the top moves freely
  kDisplacement  ///< the top nodes moved rigidly by `displacement` along the load direction; the reaction is measured
};

LoadControl load_control_from_name(std::string_view name);  ///< @throws InvalidArgument
std::string_view load_control_name(LoadControl control);

/// Boundary conditions of one load case on one mesh.
struct LoadCase {
  LoadKind kind = LoadKind::kStretch;
  LoadControl control = LoadControl::kTraction;
  double traction_pa = 0.0;      ///< traction magnitude per reference area, Pa (N/m^2); kTraction
  double displacement = 0.0;     ///< rigid move of the top nodes along `direction`, m; kDisplacement
  std::vector<int> fixed_nodes;  ///< bottom boundary nodes (min y in 2D, min z in 3D), clamped
  std::vector<int> top_nodes;    ///< nodes on the loaded top boundary
  VecX nodal_forces;             ///< consistent nodal forces, N, flat (dim * #V); zero under kDisplacement
  VecX direction;                ///< unit load direction (dim)
  double height = 0.0;           ///< extent of the mesh along the vertical axis, m
  double top_area = 0.0;         ///< loaded reference area, m^2 (edge length x thickness in 2D)
};

/// Finds the top and bottom boundaries (model/support.hpp's faces: nodes within 1e-6 of the bounding-box diagonal
/// from max / min of the vertical coordinate) and the consistent nodal forces of a uniform traction on the top facets
/// (each node of a linear facet receives traction x facet area / facet node count). A body with no flat top (a
/// scanned organ or bone) is held and loaded at its ends instead: the nodes in the lowest kEndBand (model/support.hpp)
/// of its height are fixed and the boundary facets wholly in the highest kEndBand carry the traction.
/// @param mesh       validated triangle, quad or tet mesh, m
/// @param thickness  plate thickness in 2D, m (ignored in 3D)
/// @throws InvalidArgument if no top facet or no bottom node is found, or traction is not finite
LoadCase make_load_case(const mesh::Mesh& mesh, LoadKind kind, double traction_pa, double thickness = 1.0);

/// The same supports under displacement control: the top nodes of make_load_case moved rigidly by `displacement`
/// (m, along the load direction: +z stretch, -z compress, +y shear in 3D; +y, -y, +x in 2D), no traction.
/// @throws InvalidArgument as make_load_case, or if displacement is not finite
LoadCase make_displacement_case(const mesh::Mesh& mesh, LoadKind kind, double displacement, double thickness = 1.0);

/// Applies a load case to a problem on the same mesh: clamps the fixed nodes and sets the forces; under
/// displacement control also holds the top nodes at rest + displacement x direction (problem.prescribed_positions).
/// Static solves ramp such prescribed displacements with the load factor (solve::StaticOptions::ramp_prescribed).
void apply(const LoadCase& load, Problem& problem);

/// The total force the top nodes exert on the body at `positions` (flat, m), N (dim): the internal forces
/// dE/dx summed over the top nodes, which is what holds them there: under displacement control the force on the
/// instrument that moved them (its reaction is the negative), under traction control the applied load once in
/// equilibrium. Nodes in both the top and the fixed set are skipped.
VecX top_reaction(const LoadCase& load, const Problem& problem, const VecX& positions);

/// Mean displacement of the top nodes along the load direction, m.
double mean_top_displacement(const LoadCase& load, const Problem& problem, const VecX& positions);

}  // namespace hooke::model
