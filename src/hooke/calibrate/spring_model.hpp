#pragma once
/// A calibrated mass-spring model as plain data, and its term blocks.
#include <array>
#include <hooke/mesh/mesh.hpp>
#include <hooke/model/model.hpp>
#include <memory>
#include <vector>

namespace hooke::calibrate {

struct SpringModel {
  int dim = 3;
  std::vector<std::array<int, 2>> pairs;  ///< springs (i, j), i < j
  VecX stiffness;                         ///< k per spring, N/m
  VecX rest_length;                       ///< l0 per spring, m (prestrained where the method says so)
  /// #T x 4 tets with volume terms, or #T x 3 planar triangles with area terms (any-nu-triangle); empty when the
  /// method has none.
  RowMatXi volume_tets;
  VecX volume_stiffness;  ///< k_V (or k_A) per element, J
  VecX rest_volume;       ///< V0 per tet, m^3 (or A0 per triangle, m^2)
  /// The terms' large-strain law (docs/methods/large_strain.md): the Seth-Hill exponents of the springs (m, energy
  /// k l0^2 e_m(l / l0)^2 / 2) and of the volume or area terms (q, energy k_V e_q(V / V0)^2 / 2). Both 1 (default):
  /// Hookean springs and quadratic volume terms. Any value keeps the stiffness at rest.
  double spring_exponent = 1.0;
  double volume_exponent = 1.0;
};

/// Adds the blocks of `springs` to `model`: a SpringBlock when there are springs, a TetVolumeBlock (a
/// TriangleAreaBlock for triangles) when there are volume terms. The one place where a SpringModel becomes term blocks
/// (make_model and build_model use it).
void add_spring_terms(model::Model& model, const SpringModel& springs);

/// The model of `springs` on the rest positions of `mesh`: a SpringBlock plus, when present, a TetVolumeBlock,
/// and an OrientationGuard on the mesh's elements (states with an inverted element are inadmissible).
std::shared_ptr<model::Model> make_model(const mesh::Mesh& mesh, const SpringModel& springs);

/// The springs of `springs` alone (no volume or area terms).
SpringModel springs_part(const SpringModel& springs);
/// The volume (or area) terms of `springs` alone (no springs).
SpringModel volume_part(const SpringModel& springs);

/// Linearised stiffness of `springs` at the rest positions (its Hessian there), N/m.
SparseMatrix linearised_stiffness(const mesh::Mesh& mesh, const SpringModel& springs);

}  // namespace hooke::calibrate
