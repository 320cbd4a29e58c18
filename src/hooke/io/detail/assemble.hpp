#pragma once
// Turns the elements a file holds (possibly of several kinds) into a one-kind Mesh.
#include <array>
#include <hooke/mesh/mesh.hpp>
#include <vector>

namespace hooke::io::detail {

struct RawElements {
  std::vector<std::array<int, 4>> tets, quads;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> tet_region, quad_region, triangle_region;
};

// Keeps the highest-dimensional elements: tets if any; else triangles or quads, planar (dim 2, z dropped)
// when every node has z = 0, a 3D surface otherwise. Throws ParseError-free InvalidMesh for mixed planar
// triangles and quads, and for quads on a 3D surface. `nodes` is #V x 3.
mesh::Mesh assemble(const std::string& source, const RowMatX& nodes, RawElements raw);

}  // namespace hooke::io::detail
