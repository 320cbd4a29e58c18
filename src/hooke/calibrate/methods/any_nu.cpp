// hooke's any-nu split (docs/methods/any_nu.md, cauchy_split): Lloyd's springs carry the shear modulus at the
// spring network's own Poisson ratio (E_s = 5 mu / 2 on tets, Eq. 12-13; 8 mu / 3 on triangles, Eq. 9), and a
// volume (area) term per element carries the rest of the bulk stiffness.
#include <hooke/calibrate/cauchy_split.hpp>
#include <hooke/calibrate/detail/element_springs.hpp>
#include <hooke/calibrate/methods/families.hpp>
#include <hooke/mesh/measure.hpp>

namespace hooke::calibrate::methods {
namespace {

// nu <= 1/4 (tets) or lambda* <= mu (triangles): no volume term is needed; springs only (lloyd-tet, lloyd-triangle).
void drop_zero_terms(const mesh::Mesh& m, SpringModel& out) {
  if (!out.volume_stiffness.isZero(0.0)) return;
  out.volume_tets.resize(0, m.elements.cols());
  out.volume_stiffness.resize(0);
  out.rest_volume.resize(0);
}

SpringModel any_nu_tet(const mesh::Mesh& m, const std::vector<material::Material>& materials, Method) {
  detail::EdgeAccumulator acc(m);
  for (int e = 0; e < m.element_count(); ++e) {
    const double lhat = equivalent_edge(mesh::element_measure(m, e));
    const double es = cauchy_split(material_of(materials, e)).spring_youngs_modulus;  // Eq. 12 at E_s
    acc.for_each_edge(e, [&](int s, double) { acc.add(s, 2.0 * std::sqrt(2.0) / 25.0 * lhat * es); });
  }
  SpringModel out = acc.finish();
  out.volume_tets = m.elements;
  out.volume_stiffness.resize(m.element_count());
  out.rest_volume.resize(m.element_count());
  for (int e = 0; e < m.element_count(); ++e) {
    const double v = mesh::element_measure(m, e);
    out.rest_volume(e) = v;
    out.volume_stiffness(e) =
        cauchy_split(material_of(materials, e)).volume_lambda * v;  // linearises to lambda_V V0 (tr eps)^2 / 2
  }
  drop_zero_terms(m, out);
  return out;
}

SpringModel any_nu_triangle(const mesh::Mesh& m, const std::vector<material::Material>& materials, Method) {
  detail::EdgeAccumulator acc(m);
  for (int e = 0; e < m.element_count(); ++e) {
    const material::Material& mat = material_of(materials, e);
    const double area = mesh::element_measure(m, e);
    // Eq. 9 at E_s = 8 mu / 3, the nu = 1/3 material carrying the shear modulus (cauchy_split_2d)
    const double es = cauchy_split_2d(mat).spring_youngs_modulus;
    acc.for_each_edge(e, [&](int s, double l) {
      const double a0 = std::sqrt(3.0) / 4.0 * l * l;  // equilateral triangle on this edge
      acc.add(s, es * mat.thickness * std::sqrt(3.0) / 4.0 * area / a0);
    });
  }
  SpringModel out = acc.finish();
  // area terms k_A = lambda_A t A0: (A - A0)/A0 = tr eps to first order
  out.volume_tets = m.elements;
  out.volume_stiffness.resize(m.element_count());
  out.rest_volume.resize(m.element_count());
  for (int e = 0; e < m.element_count(); ++e) {
    const material::Material& mat = material_of(materials, e);
    out.rest_volume(e) = mesh::element_measure(m, e);
    out.volume_stiffness(e) = cauchy_split_2d(mat).volume_lambda * mat.thickness * out.rest_volume(e);
  }
  drop_zero_terms(m, out);
  return out;
}

}  // namespace

std::vector<MethodEntry> any_nu_methods() {
  return {method(Method::kAnyNuTet,
                 "hooke's any-nu split: Lloyd et al. 2007 Eq. 12-13 springs at E_s = 5 mu / 2 and a volume term "
                 "k_V = (lambda - mu) V0 per tet (App. C.2) for nu >= 1/4; below, Eq. 12-13 at E (lloyd-tet)",
                 is_tets, "tets", any_nu_tet),
          method(Method::kAnyNuTriangle,
                 "hooke's any-nu split: Lloyd et al. 2007 Eq. 9 springs at E_s = 8 mu / 3 and an area term "
                 "k_A = (lambda* - mu) t A0 per triangle for lambda* >= mu (nu >= 1/3 in plane stress); below, Eq. 9 "
                 "at E",
                 is_planar_triangles, "triangles", any_nu_triangle)};
}

}  // namespace hooke::calibrate::methods
