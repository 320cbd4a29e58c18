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
  // Where the file puts each element (optional: empty, or one per element of the kind).
  std::vector<mesh::ElementOrigin> tet_origin, quad_origin, triangle_origin;

  void add_tet(const std::array<int, 4>& v, int region, mesh::ElementOrigin o) {
    tets.push_back(v);
    tet_region.push_back(region);
    tet_origin.push_back(o);
  }
  void add_quad(const std::array<int, 4>& v, int region, mesh::ElementOrigin o) {
    quads.push_back(v);
    quad_region.push_back(region);
    quad_origin.push_back(o);
  }
  void add_triangle(const std::array<int, 3>& v, int region, mesh::ElementOrigin o) {
    triangles.push_back(v);
    triangle_region.push_back(region);
    triangle_origin.push_back(o);
  }
};

// Keeps the highest-dimensional elements: tets if any; else triangles or quads, planar (dim 2, z dropped)
// when every node has z = 0, a 3D surface otherwise. Throws ParseError-free InvalidMesh for mixed planar
// triangles and quads, and for quads on a 3D surface. `nodes` is #V x 3.
mesh::Mesh assemble(const std::string& source, const RowMatX& nodes, RawElements raw);

}  // namespace hooke::io::detail
