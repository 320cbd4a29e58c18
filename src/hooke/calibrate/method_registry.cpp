#include <algorithm>
#include <hooke/calibrate/method_registry.hpp>
#include <hooke/calibrate/methods/families.hpp>
#include <hooke/core/error.hpp>
#include <stdexcept>
#include <string>

namespace hooke::calibrate {
namespace {

std::vector<MethodEntry> registry() {
  std::vector<MethodEntry> all;
  // One line per method family (calibrate/methods/).
  for (const auto family :
       {methods::van_gelder_methods, methods::lloyd_methods, methods::stiffness_fit_methods, methods::any_nu_methods})
    for (const MethodEntry& e : family()) all.push_back(e);
  std::sort(all.begin(), all.end(), [](const MethodEntry& a, const MethodEntry& b) { return a.method < b.method; });
  // Every Method has exactly one entry (a method added to the enum without its family's entry fails loudly).
  for (size_t k = 0; k < all.size(); ++k)
    if (static_cast<size_t>(all[k].method) != k || !all[k].takes || !all[k].springs)
      throw std::logic_error("the calibration method registry lacks or repeats method " + std::to_string(k));
  if (all.size() != method_names().size())
    throw std::logic_error("the calibration method registry has " + std::to_string(all.size()) + " entries for " +
                           std::to_string(method_names().size()) + " methods");
  return all;
}

}  // namespace

namespace methods {
bool is_planar_triangles(const mesh::Mesh& m) { return m.kind == mesh::ElementKind::kTriangle; }
bool is_quads(const mesh::Mesh& m) { return m.kind == mesh::ElementKind::kQuad; }
bool is_tets(const mesh::Mesh& m) { return m.kind == mesh::ElementKind::kTet; }
}  // namespace methods

std::span<const MethodEntry> method_registry() {
  static const std::vector<MethodEntry> all = registry();
  return all;
}

const MethodEntry& method_entry(Method method) { return method_registry()[static_cast<size_t>(method)]; }

std::string_view method_equation(Method method) { return method_entry(method).equation; }

}  // namespace hooke::calibrate
