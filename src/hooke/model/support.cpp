#include <hooke/mesh/measure.hpp>
#include <hooke/mesh/topology.hpp>
#include <hooke/model/support.hpp>

namespace hooke::model {
namespace {

// True when coordinate x lies within tol of the end.
bool near_end(double x, double low, double high, End end, double tol) {
  return end == End::kLow ? x <= low + tol : x >= high - tol;
}

}  // namespace

double end_tolerance(const mesh::Mesh& mesh, int axis, double band) {
  if (band == kFace) return 1e-6 * mesh::bounding_box_diagonal(mesh);
  return band * (mesh.nodes.col(axis).maxCoeff() - mesh.nodes.col(axis).minCoeff());
}

std::vector<int> end_nodes(const mesh::Mesh& mesh, int axis, End end, double band) {
  const double low = mesh.nodes.col(axis).minCoeff(), high = mesh.nodes.col(axis).maxCoeff();
  const double tol = end_tolerance(mesh, axis, band);
  std::vector<int> out;
  for (int i = 0; i < mesh.node_count(); ++i)
    if (near_end(mesh.nodes(i, axis), low, high, end, tol)) out.push_back(i);
  return out;
}

std::vector<int> end_facets(const mesh::Mesh& mesh, const RowMatXi& facets, int axis, End end, double band) {
  const double low = mesh.nodes.col(axis).minCoeff(), high = mesh.nodes.col(axis).maxCoeff();
  const double tol = end_tolerance(mesh, axis, band);
  std::vector<int> out;
  for (Eigen::Index f = 0; f < facets.rows(); ++f) {
    bool in = true;
    for (Eigen::Index k = 0; k < facets.cols(); ++k)
      in = in && near_end(mesh.nodes(facets(f, k), axis), low, high, end, tol);
    if (in) out.push_back(static_cast<int>(f));
  }
  return out;
}

BoundaryFacets boundary_facets_with_geometry(const mesh::Mesh& mesh) {
  BoundaryFacets b;
  b.facets = mesh::boundary_facets(mesh);
  b.measures = mesh::facet_measures(mesh, b.facets);
  const int d = mesh.dim(), n = static_cast<int>(b.facets.rows());
  b.normals.resize(n, d);
  b.centroids = RowMatX::Zero(n, d);
  for (int f = 0; f < n; ++f) {
    for (int a = 0; a < b.facets.cols(); ++a) b.centroids.row(f) += mesh.nodes.row(b.facets(f, a));
    b.centroids.row(f) /= static_cast<double>(b.facets.cols());
    if (d == 3) {
      const Vec3 p0 = mesh.nodes.row(b.facets(f, 0)), p1 = mesh.nodes.row(b.facets(f, 1)),
                 p2 = mesh.nodes.row(b.facets(f, 2));
      b.normals.row(f) = (p1 - p0).cross(p2 - p0).normalized();
    } else {
      const Vec2 e = mesh.nodes.row(b.facets(f, 1)) - mesh.nodes.row(b.facets(f, 0));
      b.normals.row(f) = Vec2(e.y(), -e.x()).normalized();
    }
  }
  return b;
}

std::vector<int> facing_end_facets(const mesh::Mesh& mesh, const BoundaryFacets& b, int axis, End end, double band) {
  const double low = mesh.nodes.col(axis).minCoeff(), high = mesh.nodes.col(axis).maxCoeff();
  const double extent = high - low;
  std::vector<int> out;
  for (Eigen::Index f = 0; f < b.facets.rows(); ++f) {
    const double n = b.normals(f, axis), c = b.centroids(f, axis);
    const bool facing = end == End::kLow ? n < -0.5 && c <= low + band * extent : n > 0.5 && c >= high - band * extent;
    if (facing) out.push_back(static_cast<int>(f));
  }
  return out;
}

}  // namespace hooke::model
