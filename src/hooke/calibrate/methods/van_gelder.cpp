// van Gelder 1998: the stiffness of each edge from the element measures around it, k = sum_e E t A_e / l^2
// (triangles) or sum_e E V_e / l^2 (tets).
#include <hooke/calibrate/detail/element_springs.hpp>
#include <hooke/calibrate/methods/families.hpp>
#include <hooke/mesh/measure.hpp>

namespace hooke::calibrate::methods {
namespace {

SpringModel van_gelder(const mesh::Mesh& m, const std::vector<material::Material>& materials, Method) {
  const bool tet = m.kind == mesh::ElementKind::kTet;
  detail::EdgeAccumulator acc(m);
  for (int e = 0; e < m.element_count(); ++e) {
    const material::Material& mat = material_of(materials, e);
    const double measure = mesh::element_measure(m, e) * (tet ? 1.0 : mat.thickness);
    acc.for_each_edge(e, [&](int s, double l) { acc.add(s, mat.youngs_modulus * measure / (l * l)); });
  }
  return acc.finish();
}

bool triangles_or_tets(const mesh::Mesh& m) { return is_planar_triangles(m) || is_tets(m); }

}  // namespace

std::vector<MethodEntry> van_gelder_methods() {
  return {method(Method::kVanGelder, "van Gelder 1998: k = sum_e E t A_e / l^2 (tets: E V_e / l^2)", triangles_or_tets,
                 "triangles or tets", van_gelder)};
}

}  // namespace hooke::calibrate::methods
