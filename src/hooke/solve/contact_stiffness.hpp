#pragma once
/// The stiffness a probe feels at the nodes it holds, by static condensation (the local model of multirate haptics:
/// Cavusoglu & Tendick 2000, Mark et al. 1996): the force a haptic loop renders between two deformation steps is
/// f(u) = f0 - K_c (u - u0), with f0 the deformation step's probe force at offset u0 and K_c from here.
#include <hooke/core/types.hpp>
#include <limits>
#include <vector>

namespace hooke::solve {

struct ContactStiffnessOptions {
  /// The condensation runs over the region of this many nodes nearest the held ones (Euclidean distance to the
  /// nearest held node), its boundary with the rest of the body held: a region smaller than the body gives a
  /// stiffer K_c (measured in tests/solve/test_contact_stiffness.cpp; 2 000 nodes of the 11 425-node bench cylinder
  /// render a dragged probe's force 65 % too high, the whole body 1.8 %). The whole body when it has no more nodes,
  /// which is the default: one factorisation of the body's stiffness at the grab.
  int region_nodes = std::numeric_limits<int>::max();
};

/// K_c = P^T S P, N/m (dim x dim, symmetric): S = (E^T K_rr^-1 E)^-1 is the Schur complement of the stiffness
/// `k` onto the DOFs of `nodes` over the region (the region's other DOFs relaxed, its boundary nodes, those with a
/// neighbour outside it in k's pattern, and the `fixed` DOFs held), and P moves every held node by the same offset.
/// Costs one factorisation of the region's stiffness and dim solves.
/// @param k          stiffness, N/m (dof_count square, both triangles; symmetric positive definite on the
///                   region's free DOFs: the body must be held by `fixed` or by the region's boundary)
/// @param fixed      DOFs held at their place (size dof_count)
/// @param positions  flat, m (for the region's distances)
/// @param nodes      the held nodes (non-empty, in range, not fixed)
/// @throws InvalidArgument for bad sizes or nodes; SolverFailure when the region's matrix is not positive definite
MatX contact_stiffness(const SparseMatrix& k, const std::vector<char>& fixed, const VecX& positions, int dim,
                       const std::vector<int>& nodes, const ContactStiffnessOptions& options = {});

}  // namespace hooke::solve
