#pragma once
/// Lumped masses: each element's mass split equally among its nodes.
#include <hooke/mesh/mesh.hpp>

namespace hooke::model {

/// Lumped mass per DOF (size dim * #V, kg): each element contributes density x measure (x thickness for planar
/// and surface triangles) / nodes per element to each of its nodes, on every axis.
/// @param density    kg/m^3, > 0
/// @param thickness  m, for triangles and quads (ignored for tets)
/// @throws InvalidArgument on a non-positive or non-finite density or thickness
VecX lumped_masses(const mesh::Mesh& mesh, double density, double thickness = 1.0);

}  // namespace hooke::model
