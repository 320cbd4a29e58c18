#pragma once
/// Distances between triangle surfaces: how far a remeshed surface moved from the one it stands for.
#include <hooke/mesh/mesh.hpp>

namespace hooke::mesh {

/// Distance from the point p (m) to the nearest point of the triangles `triangles` (#T x 3 rows of `nodes`), m.
/// Exact per triangle (closest point on the triangle, its edges or nodes); a uniform grid limits the search.
class SurfaceDistance {
 public:
  /// @pre triangles.rows() > 0, indices in range of nodes (#V x 3, m); both outlive this object
  SurfaceDistance(const RowMatX& nodes, const RowMatXi& triangles);
  ~SurfaceDistance();
  SurfaceDistance(const SurfaceDistance&) = delete;
  SurfaceDistance& operator=(const SurfaceDistance&) = delete;
  /// Distance from p to the surface, m.
  double operator()(const Vec3& p) const;

 private:
  struct Grid;
  const RowMatX& m_nodes;
  const RowMatXi& m_triangles;
  Grid* m_grid;
};

/// Symmetric Hausdorff distance between the triangle surfaces (nodes_a, triangles_a) and (nodes_b, triangles_b)
/// sampled at their nodes: the largest distance from a node used by one surface to the other surface, m. A lower
/// bound of the exact Hausdorff distance that equals it when the farthest points are nodes (as for a surface
/// remeshed with nodes on the original one, where it measures how far the original's nodes are cut off).
double node_hausdorff_distance(const RowMatX& nodes_a, const RowMatXi& triangles_a, const RowMatX& nodes_b,
                               const RowMatXi& triangles_b);

}  // namespace hooke::mesh
