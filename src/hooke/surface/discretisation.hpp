#pragma once
/// The volumetric discretisation of a closed surface by radial links (Arnab & Raja, Fig. 5 and Fig. 6): per
/// node, its normal, its distances to the centre, and the volumes its masses and inner springs are made from.
#include <hooke/mesh/mesh.hpp>

namespace hooke::surface {

/// Unit node normals (#V x 3) of the triangle surface with flat positions x (m): the area-weighted mean of the
/// adjacent triangles' normals, normalised. @pre every node belongs to a triangle of non-zero area
RowMatX node_normals(const RowMatXi& triangles, const Eigen::Ref<const VecX>& x);

/// Per-node quantities of the discretisation, all at rest.
struct Discretisation {
  Vec3 centre = Vec3::Zero();  ///< object centre c, m (the volume centroid unless given)
  double volume = 0.0;         ///< enclosed volume V_0, m^3
  RowMatX normals;             ///< #V x 3 unit node normals N_i (node_normals)
  RowMatX normal_cones;        ///< #V x 6 packed normal cones P_i (node_normal_cones): N_i N_i^T off creases
  VecX radial_length;          ///< L_i = |p_i - c|, m: the radial link of Fig. 5
  /// L'_i = (p_i - c) . N_i, m: the length of the node's own axis. Fig. 6 moves the centre to c_i, the point of
  /// the normal line through p_i nearest to c (c_i = p_i - L'_i N_i), so that a node's inner volume is measured
  /// along its normal; for a node in a flat face L'_i is the face's distance to c wherever the node lies.
  VecX normal_length;
  /// Sum over the triangles t containing i of vol(c, t), m^3 (Fig. 5). Each triangle's cone counts at each of
  /// its three nodes, so the sum over all nodes is 3 V_0: the masses' estimation ratio (Sec. Mass Estimation).
  VecX radial_volume;
  /// Sum over the triangles t containing i of vol(c_i, t), m^3 (Fig. 6): the inner volume that node i's anchor
  /// and bulk stiffness are made from ("sum over tet of V_t" of the stiffness equations).
  VecX normal_volume;
};

/// Discretises the closed, outward-oriented, star-shaped surface `mesh` from `centre`.
/// @pre check_closed_surface(mesh) and require_star_shaped(mesh, centre) passed
Discretisation discretise(const mesh::Mesh& mesh, const Vec3& centre);

/// The discretisation of any closed surface, star-shaped or not (a bone, an organ): hooke's reading of Fig. 6 without
/// one centre. Each node's inner point c_i lies on its inward normal line at half the body's depth there,
/// c_i = p_i - L'_i N_i with L'_i = t_i / 2 and t_i the distance along -N_i to the surface's far side (a ray cast), so
/// c_i is inside the body and its anchor axis crosses no surface (at a thin crease, whose averaged normal can point
/// out of the body, along the first of its triangles' inward normals whose ray meets the surface); normal_volume is
/// the sum of vol(c_i, t) over the
/// node's triangles as in Fig. 6, and radial_volume (the masses' estimation ratio) the same cones, since no radial
/// links exist. `centre` is the volume centroid (reported only; it may lie outside), radial_length = L'_i.
/// Cost O(#V #T) ray-triangle tests, shared over the OpenMP threads.
/// @pre check_closed_surface(mesh) passed
/// @throws InvalidMesh naming a node from which no inward ray meets a triangle (a surface oriented inwards)
Discretisation discretise_by_depth(const mesh::Mesh& mesh);

/// Node masses m_i = M r_i / sum_j r_j with r_i = radial_volume(i) (the paper's estimation ratio), kg; they sum
/// to M for any mesh, also after a local refinement (re-discretise, then call again).
/// @pre total_mass > 0, radial_volume > 0
VecX estimated_masses(const Discretisation& d, double total_mass);

}  // namespace hooke::surface
