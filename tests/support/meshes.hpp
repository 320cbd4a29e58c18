#pragma once
// Meshes for tests: structured generators with interior nodes moved at random (fixed seed).
#include <Eigen/Geometry>
#include <hooke/mesh/mesh.hpp>
#include <string>

namespace hooke::test {

// Moves every node not on the bounding box by up to `fraction` of the smallest element edge in each
// coordinate, with a fixed seed, keeping elements valid. Boundary nodes stay (so boundaries stay flat).
mesh::Mesh perturb_interior(mesh::Mesh mesh, double fraction, unsigned seed = 7);

// An irregular mesh of `kind` (triangle, quad or tet): a box of `cells` cells per side (cell size 5 mm;
// the tet box has two thirds as many cells across) with interior nodes moved by `fraction` of an edge.
mesh::Mesh irregular_mesh(mesh::ElementKind kind, int cells, double fraction);

// Two triangle surfaces as one mesh of two pieces (b's nodes after a's), named `source`.
mesh::Mesh two_pieces(const mesh::Mesh& a, const mesh::Mesh& b, const std::string& source);

// Flat node-major positions of a mesh.
VecX flat_positions(const mesh::Mesh& mesh);

// Random rotation matrix (fixed seed).
Mat3 random_rotation(unsigned seed = 3);

}  // namespace hooke::test
