#pragma once
/// Mesh: nodes plus elements of one kind. Coordinates in metres.
#include <hooke/core/types.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace hooke::mesh {

/// The element kinds hooke handles. The coordinate dimension follows from the kind.
enum class ElementKind {
  kTriangle,         ///< 3-node triangle in the plane (dim 2)
  kQuad,             ///< 4-node bilinear quadrilateral in the plane (dim 2), nodes in cyclic order
  kTet,              ///< 4-node tetrahedron (dim 3)
  kSurfaceTriangle,  ///< 3-node triangle of a surface embedded in 3D (dim 3)
};

/// Nodes per element of `kind` (3 or 4).
int nodes_per_element(ElementKind kind);
/// Coordinate dimension of `kind` (2 or 3).
int dimension(ElementKind kind);
/// Stable lower-case name: "triangle", "quad", "tet", "surface-triangle".
std::string_view element_kind_name(ElementKind kind);

/// Where a file puts an element, for messages: the number the file gives it (the Gmsh element tag, the TetGen
/// index, the VTU cell id as ParaView shows it, else the 1-based OFF/OBJ face or STL facet) and its 1-based line (0
/// in binary and VTU files).
struct ElementOrigin {
  std::int64_t number = 0;
  std::int64_t line = 0;
};

/// A mesh of one element kind.
struct Mesh {
  ElementKind kind = ElementKind::kTet;
  RowMatX nodes;           ///< #V x dim node positions, m
  RowMatXi elements;       ///< #E x nodes_per_element(kind) 0-based node indices
  Eigen::VectorXi region;  ///< #E region (physical group) tag per element; 0 where the file has none
  std::string source;      ///< file name or generator name, used in error messages
  /// Per element, where the file puts it (element_label prints it); empty for generated meshes.
  std::vector<ElementOrigin> origin;

  int dim() const { return dimension(kind); }
  int node_count() const { return static_cast<int>(nodes.rows()); }
  int element_count() const { return static_cast<int>(elements.rows()); }
};

/// Builds a mesh from arrays, filling `region` with zeros.
/// @param nodes     #V x dimension(kind) positions, m
/// @param elements  #E x nodes_per_element(kind) 0-based indices
Mesh make_mesh(ElementKind kind, RowMatX nodes, RowMatXi elements, std::string source = "");

/// How messages name one element: "tet 9 (element 60, line 410 of cylinder.msh)" for a mesh read from a file (the
/// 0-based index among the mesh's elements, then the file's own number and line), "tet 9 of generator" otherwise.
std::string element_label(const Mesh& mesh, int element);

/// Node positions stored flat (x0 y0 [z0] x1 ..., m) as #V x dim rows, the layout of Mesh::nodes.
/// @pre flat.size() is a multiple of dim
RowMatX positions_as_rows(const VecX& flat, int dim);

/// The mesh's node positions stored flat (x0 y0 [z0] x1 ..., m): the inverse of positions_as_rows.
VecX flat_positions(const Mesh& mesh);

}  // namespace hooke::mesh
