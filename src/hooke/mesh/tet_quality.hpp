#pragma once
/// Shape quality of tetrahedra as mesh generators report it: the radius ratio and the dihedral angles. Slivers
/// (four nearly coplanar nodes with no short edge) have a small radius ratio and dihedral angles near 0 and 180 deg;
/// they stiffen a model and invert first under load.
#include <array>
#include <hooke/mesh/mesh.hpp>

namespace hooke::mesh {

/// Radius ratio 3 r / R of the tet (a, b, c, d): inradius r over circumradius R, scaled to 1 for the regular tet,
/// 0 when flat. Dimensionless; the sign of the volume is ignored.
double radius_ratio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// The six dihedral angles of the tet (a, b, c, d), radians, at the edges ab, ac, ad, bc, bd, cd (the angle between
/// the two faces that meet at the edge, measured inside the tet). The regular tet has acos(1/3) = 70.53 deg at all.
/// @pre the tet is not flat
std::array<double, 6> dihedral_angles(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// The quality of a tet mesh in one place, for reports and floors.
struct TetQualityReport {
  double min_radius_ratio = 0.0;   ///< smallest radius_ratio over the tets
  double mean_radius_ratio = 0.0;  ///< mean radius_ratio
  double min_dihedral = 0.0;       ///< smallest dihedral angle, degrees
  double max_dihedral = 0.0;       ///< largest dihedral angle, degrees
  int worst_element = -1;          ///< the tet with the smallest radius ratio
  int below_floor = 0;             ///< tets with radius_ratio < the floor given
};

/// The quality of every tet of `mesh` (kind kTet), with the count of tets whose radius ratio is below
/// `radius_ratio_floor`. @pre mesh.element_count() > 0
TetQualityReport tet_quality(const Mesh& mesh, double radius_ratio_floor = 0.0);

}  // namespace hooke::mesh
