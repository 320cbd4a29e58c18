#include <hooke/mesh/mesh.hpp>

namespace hooke::mesh {

int nodes_per_element(ElementKind kind) { return kind == ElementKind::kQuad || kind == ElementKind::kTet ? 4 : 3; }

int dimension(ElementKind kind) { return kind == ElementKind::kTriangle || kind == ElementKind::kQuad ? 2 : 3; }

std::string_view element_kind_name(ElementKind kind) {
  switch (kind) {
    case ElementKind::kTriangle: return "triangle";
    case ElementKind::kQuad: return "quad";
    case ElementKind::kTet: return "tet";
    case ElementKind::kSurfaceTriangle: return "surface-triangle";
  }
  return "unknown";
}

Mesh make_mesh(ElementKind kind, RowMatX nodes, RowMatXi elements, std::string source) {
  Mesh m;
  m.kind = kind;
  m.nodes = std::move(nodes);
  m.elements = std::move(elements);
  m.region = Eigen::VectorXi::Zero(m.elements.rows());
  m.source = std::move(source);
  return m;
}

std::string element_label(const Mesh& mesh, int element) {
  std::string label = std::string(element_kind_name(mesh.kind)) + " " + std::to_string(element);
  if (mesh.origin.size() == static_cast<size_t>(mesh.element_count()) && element >= 0 &&
      element < mesh.element_count()) {
    const ElementOrigin& o = mesh.origin[static_cast<size_t>(element)];
    label += " (element " + std::to_string(o.number);
    if (o.line > 0) label += ", line " + std::to_string(o.line);
    if (!mesh.source.empty()) label += " of " + mesh.source;
    return label + ")";
  }
  if (!mesh.source.empty()) label += " of " + mesh.source;
  return label;
}

VecX flat_positions(const Mesh& mesh) { return Eigen::Map<const VecX>(mesh.nodes.data(), mesh.nodes.size()); }

RowMatX positions_as_rows(const VecX& flat, int dim) {
  return Eigen::Map<const RowMatX>(flat.data(), flat.size() / dim, dim);
}

}  // namespace hooke::mesh
