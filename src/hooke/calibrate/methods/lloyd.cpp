// Lloyd, Szekely & Harders 2007: springs whose linearised stiffness equals the FEM element's on regular elements,
// Eq. 8 (equilateral triangles), Eq. 9 (any triangle), Eq. 10-11 (squares, prestrained), Eq. 12-13 (tets) and
// Eq. 14 (tets with volume terms).
#include <hooke/calibrate/detail/element_springs.hpp>
#include <hooke/calibrate/methods/families.hpp>
#include <hooke/mesh/measure.hpp>

namespace hooke::calibrate::methods {
namespace {

SpringModel equilateral(const mesh::Mesh& m, const std::vector<material::Material>& materials, Method) {
  detail::EdgeAccumulator acc(m);
  for (int e = 0; e < m.element_count(); ++e) {
    const material::Material& mat = material_of(materials, e);
    acc.for_each_edge(e, [&](int s, double) { acc.add(s, mat.youngs_modulus * mat.thickness * std::sqrt(3.0) / 4.0); });
  }
  return acc.finish();
}

SpringModel triangle(const mesh::Mesh& m, const std::vector<material::Material>& materials, Method) {
  detail::EdgeAccumulator acc(m);
  for (int e = 0; e < m.element_count(); ++e) {
    const material::Material& mat = material_of(materials, e);
    const double area = mesh::element_measure(m, e);
    acc.for_each_edge(e, [&](int s, double l) {
      const double a0 = std::sqrt(3.0) / 4.0 * l * l;  // equilateral triangle on this edge
      acc.add(s, mat.youngs_modulus * mat.thickness * std::sqrt(3.0) / 4.0 * area / a0);
    });
  }
  return acc.finish();
}

SpringModel square(const mesh::Mesh& m, const std::vector<material::Material>& materials, Method) {
  detail::EdgeAccumulator acc(m);
  for (int e = 0; e < m.element_count(); ++e) {
    const material::Material& mat = material_of(materials, e);
    acc.for_each_edge(e, [&](int s, double) {
      const double et = mat.youngs_modulus * mat.thickness;
      acc.add(s, acc.is_diagonal(s) ? 7.0 / 16.0 * et : 5.0 / 16.0 * et);
    });
  }
  SpringModel out = acc.finish();
  for (size_t s = 0; s < out.pairs.size(); ++s)  // Eq. 11: the prestrained rest lengths
    out.rest_length(static_cast<Eigen::Index>(s)) *= acc.is_diagonal(static_cast<int>(s)) ? 6.0 / 7.0 : 6.0 / 5.0;
  return out;
}

SpringModel tet(const mesh::Mesh& m, const std::vector<material::Material>& materials, Method method) {
  detail::EdgeAccumulator acc(m);
  const double c = method == Method::kLloydTet ? 2.0 * std::sqrt(2.0) / 25.0 : 2.0 * std::sqrt(2.0) / 21.0 * 4.0 / 5.0;
  for (int e = 0; e < m.element_count(); ++e) {
    const double lhat = equivalent_edge(mesh::element_measure(m, e));
    const double youngs_modulus = material_of(materials, e).youngs_modulus;
    acc.for_each_edge(e, [&](int s, double) { acc.add(s, c * lhat * youngs_modulus); });
  }
  SpringModel out = acc.finish();
  if (method == Method::kLloydTetVolume) {  // Eq. 14's volume terms
    out.volume_tets = m.elements;
    out.volume_stiffness.resize(m.element_count());
    out.rest_volume.resize(m.element_count());
    for (int e = 0; e < m.element_count(); ++e) {
      const double v = mesh::element_measure(m, e), lhat = equivalent_edge(v);
      out.rest_volume(e) = v;
      out.volume_stiffness(e) =
          std::sqrt(2.0) / 84.0 * lhat * lhat * lhat * material_of(materials, e).youngs_modulus * 2.0 / 5.0;
    }
  }
  return out;
}

MethodEntry entry(Method value, std::string_view equation, bool (*takes)(const mesh::Mesh&), std::string_view needs,
                  double exact_nu, std::string_view exact_equation,
                  SpringModel (*springs)(const mesh::Mesh&, const std::vector<material::Material>&, Method)) {
  MethodEntry e = methods::method(value, equation, takes, needs, springs);
  e.exact_nu = exact_nu;
  e.exact_equation = exact_equation;
  e.exact_nu_text = exact_nu < 0.3 ? "1/4" : "1/3";
  return e;
}

}  // namespace

std::vector<MethodEntry> lloyd_methods() {
  std::vector<MethodEntry> out;
  out.push_back(entry(Method::kLloydEquilateral, "Lloyd et al. 2007, Eq. 8: k = sum_e sqrt(3)/4 E t",
                      is_planar_triangles, "triangles", 1.0 / 3.0, "Eq. 8", equilateral));
  out.back().regular_shape = "equilateral triangles";
  out.back().instead = "lloyd-triangle or stiffness-fit";
  out.push_back(entry(Method::kLloydTriangle, "Lloyd et al. 2007, Eq. 9: k = sum_e sqrt(3)/4 E t A_e / A_0",
                      is_planar_triangles, "triangles", 1.0 / 3.0, "Eq. 9", triangle));
  out.push_back(entry(Method::kLloydSquare,
                      "Lloyd et al. 2007, Eq. 10-11: edge 5/16 E t, diagonal 7/16 E t, prestrained", is_quads, "quads",
                      1.0 / 3.0, "Eq. 10-11", square));
  out.back().regular_shape = "squares";
  out.back().instead = "stiffness-fit";
  out.push_back(entry(Method::kLloydTet, "Lloyd et al. 2007, Eq. 12 with the equivalent edge length of Eq. 13", is_tets,
                      "tets", 0.25, "Eq. 12", tet));
  out.push_back(entry(Method::kLloydTetVolume, "Lloyd et al. 2007, Eq. 14 with the equivalent edge length of Eq. 13",
                      is_tets, "tets", 0.25, "Eq. 14", tet));
  return out;
}

}  // namespace hooke::calibrate::methods
