#pragma once
/// Figures as data: what to draw, written as JSON for scripts/plot_figures.py (matplotlib), which only draws.
/// Deformation panels follow the papers' style: spring model red over the FEM reference black.
#include <array>
#include <filesystem>
#include <hooke/mesh/mesh.hpp>
#include <string>
#include <variant>
#include <vector>

namespace hooke::experiments {

/// One mesh drawn as line segments between node positions.
struct MeshDrawing {
  std::string label;                      ///< legend entry ("MSM", "FEM", "rest")
  std::string color;                      ///< matplotlib colour name
  double line_width = 1.0;                ///< points
  std::vector<std::array<int, 2>> edges;  ///< node pairs to draw
  RowMatX positions;                      ///< #V x dim node positions, m (drawn in cm)
};

/// A 2D view of one or more deformed meshes; 3D meshes are projected onto the axes `axes`.
struct DeformationPanel {
  std::string title;
  std::array<int, 2> axes{0, 1};  ///< coordinates drawn horizontally and vertically
  std::vector<MeshDrawing> drawings;
};

/// One curve of a line plot.
struct Series {
  std::string label;
  std::string style;  ///< matplotlib format string, e.g. "o" or "k-"
  std::vector<double> x, y;
};

/// A line plot.
struct CurvePanel {
  std::string title, xlabel, ylabel;
  std::vector<Series> series;
};

/// A figure: panels in one row, saved as `name`.png beside its JSON spec.
struct Figure {
  std::string name;   ///< file stem, e.g. "fig09_membrane"
  std::string title;  ///< suptitle
  std::vector<std::variant<DeformationPanel, CurvePanel>> panels;
};

/// Edges that show a mesh: element edges in 2D (quad sides, not their diagonals), edges of the boundary
/// surface for tets (a projected wireframe).
std::vector<std::array<int, 2>> drawing_edges(const mesh::Mesh& mesh);

/// A deformation panel: the FEM positions black, the spring-model positions red, the rest shape light grey.
/// @param fem_mesh, spring_mesh  may differ (resolution studies); positions are flat (dim * #V), m
DeformationPanel deformation_panel(const std::string& title, const mesh::Mesh& fem_mesh, const VecX& fem_positions,
                                   const mesh::Mesh& spring_mesh, const VecX& spring_positions);

/// Writes `dir`/`figure.name`.json atomically (the spec plot_figures.py reads).
void write_figure_spec(const std::filesystem::path& dir, const Figure& figure);

}  // namespace hooke::experiments
