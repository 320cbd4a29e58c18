#pragma once
/// The calibration methods' registry (docs/architecture.md, "Where a new piece goes"): each method family lives in one
/// file under calibrate/methods/ and lists its methods as entries; the registry (method_registry.cpp) holds one line
/// per family. method_equation, validity_warnings and calibrate read the entries, so no switch over the methods is
/// written anywhere else.
#include <hooke/calibrate/method.hpp>
#include <span>
#include <string_view>

namespace hooke::calibrate {

/// One calibration method.
struct MethodEntry {
  Method method = Method::kLloydTet;
  std::string_view equation;  ///< where its constants come from, one line (method_equation)
  /// The element kinds it takes: `takes` on the mesh, `needs` naming them for the error ("triangles", "tets").
  bool (*takes)(const mesh::Mesh& mesh) = nullptr;
  std::string_view needs;
  /// Where its derivation is exact, for validity_warnings: the Poisson ratio (< 0: any), the equation that fixes it
  /// and its printed value ("1/4"), the regular element it assumes ("squares", "equilateral triangles"; empty: any
  /// shape), and what to use instead.
  double exact_nu = -1.0;
  std::string_view exact_equation, exact_nu_text, regular_shape, instead;
  /// The springs (and volume or area terms) on a mesh it takes, for one material or one per element (validated).
  SpringModel (*springs)(const mesh::Mesh& mesh, const std::vector<material::Material>& materials,
                         Method method) = nullptr;
};

/// Every method's entry, in the order of Method.
std::span<const MethodEntry> method_registry();
/// The entry of `method`.
const MethodEntry& method_entry(Method method);

}  // namespace hooke::calibrate
