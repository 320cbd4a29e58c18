#pragma once
/// Structured meshes of the papers' test objects (Lloyd et al. 2007, Sec. 5; Arnab & Raja, Table 1).
#include <hooke/mesh/mesh.hpp>

namespace hooke::mesh {

/// Planar membrane of equilateral triangles: `rows` rows of nodes, alternating `long_row` nodes and
/// `long_row - 1` nodes (the short rows centred), edge length `edge` m, bottom row at y = 0.
/// rows = 7, long_row = 6, edge = 0.01 gives Lloyd Sec. 5.1's membrane: 39 nodes, 92 edges, 5.2 cm high.
/// @pre rows >= 2, long_row >= 2, edge > 0
Mesh equilateral_membrane(int rows, int long_row, double edge);

/// Regular hexagon of equilateral triangles, `rings` triangles from the centre to each side, side length
/// `side` m, centred at the origin with two sides horizontal (Lloyd Fig. 3's hexagon).
/// @pre rings >= 1, side > 0
Mesh hexagon_membrane(int rings, double side);

/// Rectangle [0, width] x [0, height] split into nx x ny axis-aligned quads (counter-clockwise).
/// @pre nx, ny >= 1; width, height > 0 (m)
Mesh rectangle_quads(double width, double height, int nx, int ny);

/// How each cell of a rectangle is split into two triangles.
enum class Diagonal {
  kRising,      ///< every cell split along its (0,0)-(1,1) diagonal
  kFalling,     ///< every cell split along its (1,0)-(0,1) diagonal
  kAlternating  ///< checkerboard of the two (a "union jack"-free symmetric pattern)
};

/// Rectangle [0, width] x [0, height] split into nx x ny cells of two triangles each.
/// @pre nx, ny >= 1; width, height > 0 (m)
Mesh rectangle_triangles(double width, double height, int nx, int ny, Diagonal diagonal = Diagonal::kAlternating);

/// Box [0, lx] x [0, ly] x [0, lz] split into nx x ny x nz cubes of six tets each (all sharing the cube's
/// main diagonal, so neighbouring cubes conform). (nx+1)(ny+1)(nz+1) nodes, 6 nx ny nz positive tets.
/// @pre n* >= 1; l* > 0 (m)
Mesh tet_box(double lx, double ly, double lz, int nx, int ny, int nz);

/// Cylinder of `radius` and `height` (m), axis along z from z = 0, without slivers: the cross-section is an
/// O-grid (a square of n/2 x n/2 cells in the middle, a ring of max(1, n/4) cells out to the circle, corners of
/// the square at 45 degrees, circle nodes at equal angles), each quad split along its shorter diagonal, extruded
/// in `layers` equal layers; each prism is cut into three tets along the diagonals through the smallest node
/// index of its faces (conforming; Dompierre et al. 1999). Deterministic. (The earlier square-to-disc map turned
/// the square's corner cells into flat tets of quality 0.03 that spring models invert under gravity.)
/// Nodes ((n/2 + 1)^2 + 2 n max(1, n/4)) (layers + 1), tets 6 (n^2/4 + 2 n max(1, n/4)) layers.
/// @pre n >= 2 even, layers >= 1, radius, height > 0
Mesh tet_cylinder(double radius, double height, int n, int layers);

/// Closed surface of the cube [0, size]^3 with n x n squares per face, each split into two triangles,
/// oriented with outward normals: 6 n^2 + 2 nodes (602, 1352, 2402 for n = 10, 15, 20), 12 n^2 triangles.
/// @pre n >= 1, size > 0 (m)
Mesh cube_surface(int n, double size);
/// Closed surface of the sphere of `radius` (m) about the origin: `rings` bands of latitude and `segments`
/// meridians, triangles fanned at the poles and two per cell elsewhere, outward oriented. 2 + (rings - 1)
/// segments nodes (rings 26, segments 40: 1 002, the "sphere (1000 nodes)" of Arnab & Raja's Table 2); the
/// triangles shrink towards the poles: an irregular mesh topology.
/// @pre rings >= 2, segments >= 3, radius > 0
Mesh uv_sphere_surface(int rings, int segments, double radius);
/// Tet mesh of the volume inside a closed surface that is star-shaped from `centre` (m): `layers` scaled copies
/// of the surface towards the centre, a cone of tets from the centre to the innermost copy, and three tets per
/// prism between copies (split along diagonals chosen by node index, so neighbouring prisms conform). Its
/// boundary is the surface itself: the volumetric counterpart of a surface model (Arnab & Raja, Table 2).
/// 1 + layers #V nodes, (3 layers - 2) #T tets.
/// @pre surface is outward-oriented and star-shaped from centre; layers >= 1
Mesh tetrahedralise_radially(const Mesh& surface, const Vec3& centre, int layers);

}  // namespace hooke::mesh
