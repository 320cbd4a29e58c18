#include <hooke/core/atomic_file.hpp>
#include <hooke/experiments/figure.hpp>
#include <hooke/mesh/topology.hpp>
#include <nlohmann/json.hpp>
#include <set>

namespace hooke::experiments {
namespace {

nlohmann::json rows_json(const RowMatX& m) {
  nlohmann::json out = nlohmann::json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index k = 0; k < m.cols(); ++k) row.push_back(m(i, k));
    out.push_back(row);
  }
  return out;
}

nlohmann::json panel_json(const DeformationPanel& p) {
  nlohmann::json d = nlohmann::json::array();
  for (const auto& m : p.drawings)
    d.push_back({{"label", m.label},
                 {"color", m.color},
                 {"line_width", m.line_width},
                 {"edges", m.edges},
                 {"positions", rows_json(m.positions)}});
  return {{"type", "deformation"}, {"title", p.title}, {"axes", p.axes}, {"drawings", d}};
}

nlohmann::json panel_json(const CurvePanel& p) {
  nlohmann::json s = nlohmann::json::array();
  for (const auto& c : p.series) s.push_back({{"label", c.label}, {"style", c.style}, {"x", c.x}, {"y", c.y}});
  return {{"type", "curves"}, {"title", p.title}, {"xlabel", p.xlabel}, {"ylabel", p.ylabel}, {"series", s}};
}

}  // namespace

std::vector<std::array<int, 2>> drawing_edges(const mesh::Mesh& mesh) {
  if (mesh.kind != mesh::ElementKind::kTet) {
    std::set<std::array<int, 2>> edges;
    const int n = static_cast<int>(mesh.elements.cols());
    for (int e = 0; e < mesh.element_count(); ++e)
      for (int a = 0; a < n; ++a) {
        const int i = mesh.elements(e, a), j = mesh.elements(e, (a + 1) % n);
        edges.insert({std::min(i, j), std::max(i, j)});
      }
    return {edges.begin(), edges.end()};
  }
  const RowMatXi faces = mesh::boundary_facets(mesh);
  std::set<std::array<int, 2>> edges;
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int a = 0; a < 3; ++a) {
      const int i = faces(f, a), j = faces(f, (a + 1) % 3);
      edges.insert({std::min(i, j), std::max(i, j)});
    }
  return {edges.begin(), edges.end()};
}

DeformationPanel deformation_panel(const std::string& title, const mesh::Mesh& fem_mesh, const VecX& fem_positions,
                                   const mesh::Mesh& spring_mesh, const VecX& spring_positions) {
  DeformationPanel p;
  p.title = title;
  if (fem_mesh.dim() == 3) p.axes = {1, 2};  // the shear direction (y) across, the load axis (z) up
  p.drawings.push_back({"rest", "lightgrey", 0.5, drawing_edges(fem_mesh), fem_mesh.nodes});
  p.drawings.push_back(
      {"FEM", "black", 0.8, drawing_edges(fem_mesh), mesh::positions_as_rows(fem_positions, fem_mesh.dim())});
  p.drawings.push_back(
      {"MSM", "red", 0.8, drawing_edges(spring_mesh), mesh::positions_as_rows(spring_positions, spring_mesh.dim())});
  if (fem_mesh.dim() == 3)
    for (auto& d : p.drawings) d.line_width *= 0.4;
  return p;
}

void write_figure_spec(const std::filesystem::path& dir, const Figure& figure) {
  nlohmann::json panels = nlohmann::json::array();
  for (const auto& p : figure.panels) std::visit([&](const auto& v) { panels.push_back(panel_json(v)); }, p);
  const nlohmann::json j = {{"name", figure.name}, {"title", figure.title}, {"panels", panels}};
  create_output_folder(dir);
  write_file_atomically(dir / (figure.name + ".json"), [&](std::ostream& o) { o << j.dump() << '\n'; });
}

}  // namespace hooke::experiments
