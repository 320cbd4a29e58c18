#pragma once
/// The normal cone of a surface node: which directions push or pull a node straight through the surface. Arnab &
/// Raja blend an anchor's stiffness by |N_i . F^_i|, the normal component of the acting force. At a crease (a
/// cube's edge or corner) a node lies on faces with different normals and its averaged N_i is none of them: a force
/// normal to either face compresses the body through that node. hooke's reading (docs/surface.md, "Creases"):
/// the blend's weight is c = sqrt(F^T P_i F^) with P_i a symmetric matrix, N_i N_i^T at a smooth node, so that
/// c = |N_i . F^| as printed, and the projector onto the faces' normals at a crease (P = N N^T + d d^T at a cube
/// edge, d the in-plane direction across the crease; P = I at a cube corner).
#include <hooke/core/types.hpp>

namespace hooke::surface {

/// A node's normal cone packed in one row of 6: P_xx, P_yy, P_zz, P_xy, P_xz, P_yz.
using ConeRow = Eigen::Matrix<double, 1, 6>;
/// The symmetric P of a packed row.
Mat3 unpack_cone(const ConeRow& row);
/// The packed row of the symmetric P.
ConeRow pack_cone(const Mat3& p);

/// The normal cones (#V x 6, packed) of the triangle surface with flat positions x (m) and unit node normals N
/// (node_normals). With M = sum over the node's triangles of A_t N_t N_t^T, the tangential moment
/// T = (I - N N^T) M (I - N N^T) / (N^T M N) has the eigenvalues tan^2(alpha/2) of a symmetric crease of dihedral
/// angle alpha between the node's faces (1 at a right-angled edge, 0 on a plane). P = N N^T + sum_k s(t_k) e_k e_k^T
/// over T's eigenpairs, with s the smoothstep from t = tan^2(12.5 deg) (alpha = 25 deg: a smooth surface at any
/// usable resolution, P = N N^T exactly) to tan^2(30 deg) (alpha = 60 deg: a crease, a full face normal).
/// @pre every node belongs to a triangle of non-zero area, N the node_normals of the same surface
RowMatX node_normal_cones(const RowMatXi& triangles, const Eigen::Ref<const VecX>& x, const RowMatX& normals);

/// The packed cone N N^T of a smooth node with unit normal N (the paper's blend).
ConeRow smooth_cone(const Vec3& normal);

}  // namespace hooke::surface
