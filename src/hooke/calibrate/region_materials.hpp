#pragma once
/// Materials by region: a mesh's element regions (Gmsh physical groups, VTU `region`, TetGen attributes, an image's
/// labels) each with its own E and nu, the tissues of one body (docs/regions.md). Every calibration method computes
/// its terms element by element with that element's material, so a spring on an interface edge sums the
/// contributions of the tissues on both sides, and the FEM reference uses the same regions.
#include <hooke/material/material.hpp>
#include <hooke/mesh/mesh.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hooke::calibrate {

/// One region's elasticity; everything else (law, plane, thickness) is the model's material.
struct RegionMaterial {
  int region = 0;               ///< the elements' tag (Mesh::region)
  double youngs_modulus = 0.0;  ///< E, Pa, > 0
  double poisson_ratio = 0.0;   ///< nu, in (-1, 0.5)

  bool operator==(const RegionMaterial&) const = default;
};

/// Parses "REGION=E,NU" (an integer tag, E in Pa, nu), as `--material` gives it.
/// @throws InvalidArgument naming the text and the form expected; InvalidMaterial for E or nu out of range
RegionMaterial parse_region_material(std::string_view text);

/// Checks every entry (E > 0, -1 < nu < 0.5, finite) and that no region is listed twice.
/// @throws InvalidMaterial naming the region; InvalidArgument for a region listed twice
void validate_regions(const std::vector<RegionMaterial>& regions);

/// The material of each element of `mesh`: `base` with E and nu replaced where the element's region is listed.
/// With no regions, the single entry {base} (what calibrate() and the FEM take for one material).
/// @throws InvalidArgument when a listed region has no element in `mesh` (naming the regions it has), or when
///   `require_all` and an element's region is not listed (naming that region and its element count)
std::vector<material::Material> element_materials(const mesh::Mesh& mesh, const material::Material& base,
                                                  const std::vector<RegionMaterial>& regions, bool require_all = false);

/// E and nu of the elements that `regions` does not list: `youngs_modulus` and `poisson_ratio` when both are given;
/// when both are NaN (not given), the first region's, and then every element of `mesh` must be in a listed region.
/// @throws InvalidArgument when only one of the two is given, neither is given without regions, or (neither given) an
///   element's region is not listed, naming it
std::pair<double, double> unlisted_elasticity(const mesh::Mesh& mesh, const std::vector<RegionMaterial>& regions,
                                              double youngs_modulus, double poisson_ratio);

/// One line per material of the body: "region 2: E 25000 Pa, nu 0.45, 310 tets" for each listed region, then
/// "other regions: ..." when elements are left to `base` (reports of hooke calibrate and the viewer).
std::vector<std::string> describe_region_materials(const mesh::Mesh& mesh, const material::Material& base,
                                                   const std::vector<RegionMaterial>& regions);

/// The element regions of `mesh` with their element counts, "1 (1 204 tets), 2 (310 tets)", for messages.
std::string describe_regions(const mesh::Mesh& mesh);

}  // namespace hooke::calibrate
