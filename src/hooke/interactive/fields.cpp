#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/name_table.hpp>
#include <hooke/interactive/fields.hpp>
#include <hooke/mesh/topology.hpp>
#include <set>

namespace hooke::interactive {

SurfaceView surface_view(const mesh::Mesh& mesh) {
  SurfaceView v;
  switch (mesh.kind) {
    case mesh::ElementKind::kTet: v.triangles = mesh::boundary_facets(mesh); break;
    case mesh::ElementKind::kSurfaceTriangle:
    case mesh::ElementKind::kTriangle: v.triangles = mesh.elements; break;
    case mesh::ElementKind::kQuad:
      v.triangles.resize(2 * mesh.element_count(), 3);
      for (int e = 0; e < mesh.element_count(); ++e) {
        const auto q = mesh.elements.row(e);
        v.triangles.row(2 * e) << q(0), q(1), q(2);
        v.triangles.row(2 * e + 1) << q(0), q(2), q(3);
      }
      break;
  }
  std::set<std::array<int, 2>> edges;
  std::set<int> nodes;
  for (Eigen::Index f = 0; f < v.triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = v.triangles(f, k), b = v.triangles(f, (k + 1) % 3);
      edges.insert({std::min(a, b), std::max(a, b)});
      nodes.insert(a);
    }
  if (mesh.kind == mesh::ElementKind::kQuad) {  // the quads' sides, not the split diagonals
    edges.clear();
    for (const auto& e : mesh::unique_edges(mesh)) edges.insert(e);
  }
  v.edges.assign(edges.begin(), edges.end());
  v.nodes.assign(nodes.begin(), nodes.end());
  return v;
}

namespace {
constexpr NameTable<ColorField, 6> kColorFields{"colour map",
                                                {{{ColorField::kNone, "none"},
                                                  {ColorField::kDisplacement, "displacement"},
                                                  {ColorField::kError, "error"},
                                                  {ColorField::kStrain, "strain"},
                                                  {ColorField::kWeights, "weights"},
                                                  {ColorField::kYoung, "young"}}}};
}  // namespace

ColorField color_field_from_name(const std::string& name) { return kColorFields.from_name(name); }
std::string color_field_name(ColorField f) { return std::string(kColorFields.name(f)); }

std::string color_field_unit(ColorField f) {
  switch (f) {
    case ColorField::kDisplacement:
    case ColorField::kError: return "m";
    case ColorField::kStrain:
    case ColorField::kWeights: return "1";
    case ColorField::kYoung: return "Pa";
    case ColorField::kNone: break;
  }
  return "";
}

VecX node_youngs_modulus(const calibrate::CalibratedModel& model) {
  const std::vector<material::Material> materials = calibrate::element_materials(model);
  VecX out = VecX::Zero(model.mesh.node_count());
  if (materials.size() == 1 || model.mesh.element_count() == 0) return out.setConstant(materials[0].youngs_modulus);
  for (int e = 0; e < model.mesh.element_count(); ++e)
    for (Eigen::Index k = 0; k < model.mesh.elements.cols(); ++k) {
      double& v = out(model.mesh.elements(e, k));
      v = std::max(v, materials[static_cast<std::size_t>(e)].youngs_modulus);
    }
  return out;
}

VecX displacement_magnitude(const VecX& x, const VecX& rest, int dim) { return node_distance(x, rest, dim); }

VecX node_distance(const VecX& x, const VecX& y, int dim) {
  const Eigen::Index n = x.size() / dim;
  VecX out(n);
  for (Eigen::Index i = 0; i < n; ++i) out(i) = (x.segment(dim * i, dim) - y.segment(dim * i, dim)).norm();
  return out;
}

VecX spring_strain(const calibrate::SpringModel& springs, const VecX& x, int node_count) {
  const int d = springs.dim;
  VecX sum = VecX::Zero(node_count), count = VecX::Zero(node_count);
  for (size_t s = 0; s < springs.pairs.size(); ++s) {
    const auto [i, j] = springs.pairs[s];
    const double l0 = springs.rest_length(static_cast<Eigen::Index>(s));
    const double strain = (x.segment(d * j, d) - x.segment(d * i, d)).norm() / l0 - 1.0;
    sum(i) += strain;
    sum(j) += strain;
    count(i) += 1.0;
    count(j) += 1.0;
  }
  for (int i = 0; i < node_count; ++i) sum(i) = count(i) > 0.0 ? sum(i) / count(i) : 0.0;
  return sum;
}

std::array<float, 3> colormap(double t) {
  // Three anchors, linear in between: dark blue, teal, yellow (lightness rises monotonically).
  static constexpr float kAnchors[3][3] = {{0.18f, 0.10f, 0.42f}, {0.12f, 0.56f, 0.55f}, {0.98f, 0.90f, 0.15f}};
  t = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.0;
  const int k = t < 0.5 ? 0 : 1;
  const float f = static_cast<float>(t < 0.5 ? 2.0 * t : 2.0 * t - 1.0);
  return {kAnchors[k][0] + f * (kAnchors[k + 1][0] - kAnchors[k][0]),
          kAnchors[k][1] + f * (kAnchors[k + 1][1] - kAnchors[k][1]),
          kAnchors[k][2] + f * (kAnchors[k + 1][2] - kAnchors[k][2])};
}

}  // namespace hooke::interactive
