#pragma once
/// The stiffness a probe feels at the nodes it holds, by static condensation (the local model of multirate haptics:
/// Cavusoglu & Tendick 2000, Mark et al. 1996): the force a haptic loop renders between two deformation steps is
/// f(u) = f0 - K_c (u - u0), with f0 the deformation step's probe force at offset u0 and K_c from here.
#include <hooke/core/types.hpp>
#include <hooke/model/model.hpp>
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

/// contact_stiffness with the displacement fields it condenses.
struct ContactResponse {
  MatX stiffness;  ///< K_c, N/m (dim x dim)
  /// dof_count x dim: column a is the body's linear static displacement, m per m, when every held node moves by a
  /// unit offset along axis a (1 on those nodes' DOFs along a, 0 on the fixed DOFs and outside the region)
  MatX modes;
};
/// Same arguments, preconditions and errors as contact_stiffness.
ContactResponse contact_response(const SparseMatrix& k, const std::vector<char>& fixed, const VecX& positions, int dim,
                                 const std::vector<int>& nodes, const ContactStiffnessOptions& options = {});

/// The condensed energy's third derivative at `positions`, N/m^2 (dim x dim^2): T(c, a dim + b) = E'''[X_a, X_b,
/// X_c] with X the `modes` of contact_response, from central differences of `model`'s gradient. For the energy
/// Psi(u) the body stores when the probe moves by u and the rest relaxes, Psi''' = E'''[X, X, X] at an
/// equilibrium (the terms with the relaxation's second derivative vanish there), so the probe force is
/// f(u0 + d) = f0 - K d - T(d, d) / 2 to second order: what the linear local model misses of a stretched body's
/// stiffening (docs/simulation.md, multirate haptics).
/// @param step  the largest node displacement of a difference, m (> 0; small against an element: the body must
///              not invert within it)
/// @throws InvalidArgument for sizes that do not match; SolverFailure when the gradient is not finite there
MatX contact_curvature(const model::Model& model, const VecX& positions, const MatX& modes, double step,
                       const model::Interaction* interaction = nullptr);

}  // namespace hooke::solve
