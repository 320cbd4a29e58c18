#pragma once
/// What a viewer draws of a model: its outer surface, and per-node scalar fields for colour maps (displacement
/// magnitude, distance to a reference solution, spring strain; the surface model's Eq. 4 weights come from
/// surface::VolumePenaltyBlock::weights).
#include <array>
#include <hooke/calibrate/calibrated_model.hpp>
#include <string>
#include <vector>

namespace hooke::interactive {

/// The triangles and edges to draw.
struct SurfaceView {
  RowMatXi triangles;  ///< #F x 3 node indices: boundary facets of a tet mesh (outward), the triangles of a surface
                       ///< or planar mesh, planar quads split in two
  std::vector<std::array<int, 2>> edges;  ///< unique edges of `triangles` (the wireframe)
  std::vector<int> nodes;                 ///< nodes on the drawn surface, ascending
};

/// The surface of `mesh` to draw. @pre a validated mesh
SurfaceView surface_view(const mesh::Mesh& mesh);

enum class ColorField { kNone, kDisplacement, kError, kStrain, kWeights, kYoung };
ColorField color_field_from_name(
    const std::string& name);  ///< none|displacement|error|strain|weights|young; @throws InvalidArgument
std::string color_field_name(ColorField field);
std::string color_field_unit(ColorField field);  ///< "m", "m", "1" (strain), "1" (weights), "Pa", "" for none

/// |x_i - X_i| per node, m. @pre x, rest flat of equal size, a multiple of dim
VecX displacement_magnitude(const VecX& x, const VecX& rest, int dim);
/// |x_i - y_i| per node, m (the distance to a reference solution y, e.g. the FEM's). @pre equal sizes
VecX node_distance(const VecX& x, const VecX& y, int dim);
/// Mean spring strain l / l0 - 1 per node over the springs at that node (0 where there are none): stretch > 0,
/// compression < 0. @pre x flat, dim per node, springs on its nodes
VecX spring_strain(const calibrate::SpringModel& springs, const VecX& x, int node_count);
/// Young's modulus per node, Pa: the largest of its elements' (calibrate::element_materials), so that the tissues
/// of a model with regions show, an interface node with the stiffer one's. @pre a model that validate_model accepts
VecX node_youngs_modulus(const calibrate::CalibratedModel& model);
/// A colour for value t in [0, 1] (clamped) on a perceptually ordered map (dark blue -> teal -> yellow), RGB in
/// [0, 1]. Used by the viewer's surfaces and its colour bar alike.
std::array<float, 3> colormap(double t);

}  // namespace hooke::interactive
