#pragma once
/// Mesh validation on load: indices, finite coordinates, degenerate and inverted elements, orientation.
#include <array>
#include <hooke/mesh/mesh.hpp>
#include <vector>

namespace hooke::mesh {

struct ValidationOptions {
  /// An element whose shape quality (1 for the regular shape, 0 when flat) is below this is degenerate.
  /// Quality is 4*sqrt(3)*A / sum(l^2) for triangles and 6*sqrt(2)*V / l_rms^3 for tets. Default 1e-6.
  double min_quality = 1e-6;
  /// Reorder 2D elements given clockwise (and tets of a mesh given entirely with negative volume) so
  /// that all measures are positive, with a warning. When false such elements are errors. Default true.
  bool fix_orientation = true;
};

struct ValidationReport {
  int reoriented_elements = 0;    ///< elements whose node order was reversed
  std::vector<int> unused_nodes;  ///< nodes referenced by no element (kept, reported)
  /// Pairs of used nodes at the same point (closer than 1e-12 of the bounding-box diagonal), lower index first:
  /// a cracked mesh, whose elements on either side are not connected (kept, reported).
  std::vector<std::array<int, 2>> coincident_nodes;
};

/// Checks `mesh` in place and makes 2D elements counter-clockwise.
/// @throws InvalidMesh naming the element (and mesh.source) for: an index out of range, a repeated node,
///   a non-finite coordinate, a degenerate element, a non-convex quad, or a tet inverted against the rest
///   of the mesh. Unused and coincident nodes are only reported (log warning and report).
ValidationReport validate(Mesh& mesh, const ValidationOptions& options = {});

/// Shape quality of element `e` in [0, 1] (signed: negative when inverted); see ValidationOptions.
double element_quality(const Mesh& mesh, int e);

}  // namespace hooke::mesh
