#pragma once
/// Picking on a drawn surface: which surface point a mouse ray hits, and which nodes a grab takes.
#include <hooke/core/types.hpp>
#include <optional>
#include <vector>

namespace hooke::interactive {

struct SurfaceHit {
  int triangle = -1;          ///< row of the triangle list
  double distance = 0.0;      ///< along the ray, in units of |direction|
  Vec3 point = Vec3::Zero();  ///< m
  int nearest_node = -1;      ///< the triangle's node closest to the point
};

/// The first triangle a ray origin + s direction (s > 0) hits (Moller-Trumbore, both faces).
/// @param positions  #V x 3 node positions, m
/// @param triangles  #F x 3 node indices
std::optional<SurfaceHit> pick_surface(const RowMatX& positions, const RowMatXi& triangles, const Vec3& origin,
                                       const Vec3& direction);

/// The nodes of `candidates` within `radius` (m) of `centre`, always including `nearest` (radius 0: only it).
std::vector<int> nodes_within(const RowMatX& positions, const std::vector<int>& candidates, const Vec3& centre,
                              double radius, int nearest);

/// Positions flat with `dim` per node as #V x 3 rows, m: what a viewer draws. A planar mesh's (x, y) becomes
/// (x, 0, y), so that the vertical axis (y in 2D, z in 3D) is z in both.
RowMatX positions_3d(const VecX& flat, int dim);
/// The model's components (dim) of a vector in drawing coordinates: the inverse of positions_3d's map.
VecX from_3d(const Vec3& v, int dim);

}  // namespace hooke::interactive
