#pragma once
/// The method "auto": for a mesh's element kind and a material's nu, the calibration method with the smallest
/// measured worst-case error against the linear FEM, read from a table the nu-range study writes
/// (experiments::reproduce_nu_range; method_table.inc; docs/nu_range.md).
#include <hooke/material/material.hpp>
#include <hooke/mesh/mesh.hpp>
#include <string>
#include <vector>

namespace hooke::calibrate {

/// One entry of the table: a method's worst relative L2 node error against the linear FEM at small strain, over
/// the study's meshes of one table and its three loads (stretch, compression, shear), at one nu.
struct MeasuredError {
  std::string table;               ///< method_table_name(): "tet", "triangle plane-stress", "triangle plane-strain"
  double poisson = 0.0;            ///< nu
  std::string method;              ///< calibration method name
  double worst_relative_l2 = 0.0;  ///< >= 0
  int cases = 0;                   ///< comparisons the worst case is taken over
};

/// The library's table (src/hooke/calibrate/method_table.inc, as `hooke reproduce nu-range` wrote it).
const std::vector<MeasuredError>& measured_errors();

/// The table a mesh of `kind` with `material` is chosen from: "tet", "triangle plane-stress" or "triangle
/// plane-strain"; empty for kinds the study does not measure (quads, surface triangles).
std::string method_table_name(mesh::ElementKind kind, const material::Material& material);

struct MethodChoice {
  std::string method;  ///< a calibration method name
  std::string reason;  ///< one line: what was compared and the errors measured
};

/// The method for `kind` and `material.poisson_ratio`: per method, the worst-case error interpolated linearly in nu
/// between the table's two nearest values (the nearest one outside its range), then the smallest (ties: the method
/// that is best at more of the table's nu). Surface-triangle meshes get the tet pick, since calibrate_model
/// tetrahedralizes a closed surface first (--method surface, Arnab & Raja's model, stays explicit); quads, which the
/// study does not measure, "stiffness-fit" (the per-element fit of the FEM stiffness, exact on the squares of
/// Eq. 10-11), each with that reason.
/// @throws InvalidArgument when `table` has no entry for the kind's table
MethodChoice choose_method(mesh::ElementKind kind, const material::Material& material,
                           const std::vector<MeasuredError>& table = measured_errors());

/// `rows` as the C++ initialiser list method_table.inc holds (one entry per line), for the study to write.
std::string method_table_source(const std::vector<MeasuredError>& rows);

}  // namespace hooke::calibrate
