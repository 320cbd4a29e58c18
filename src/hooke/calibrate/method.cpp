#include <cmath>
#include <hooke/calibrate/detail/element_springs.hpp>
#include <hooke/calibrate/method.hpp>
#include <hooke/calibrate/stiffness_fit.hpp>
#include <hooke/core/error.hpp>
#include <hooke/mesh/measure.hpp>

namespace hooke::calibrate {
namespace {

struct Named {
  Method method;
  std::string_view name;
};
constexpr Named kNames[] = {
    {Method::kVanGelder, "vangelder"},          {Method::kLloydEquilateral, "lloyd-equilateral"},
    {Method::kLloydTriangle, "lloyd-triangle"}, {Method::kLloydSquare, "lloyd-square"},
    {Method::kLloydTet, "lloyd-tet"},           {Method::kLloydTetVolume, "lloyd-tet-volume"},
    {Method::kStiffnessFit, "stiffness-fit"},   {Method::kStiffnessFitVolume, "stiffness-fit-volume"}};

void require_kind(const mesh::Mesh& m, bool ok, Method method, const char* what) {
  if (!ok)
    throw InvalidArgument("method '" + std::string(method_name(method)) + "' needs " + what + ", not a " +
                          std::string(mesh::element_kind_name(m.kind)) + " mesh");
}

// Equivalent edge length of a tet from its volume (Eq. 13): V = l^3 sqrt(2)/12.
double equivalent_edge(double volume) { return std::cbrt(volume * 12.0 / std::sqrt(2.0)); }

}  // namespace

Method method_from_name(std::string_view name) {
  for (const auto& n : kNames)
    if (n.name == name) return n.method;
  std::string all;
  for (const auto& n : kNames) all += (all.empty() ? "" : ", ") + std::string(n.name);
  throw InvalidArgument("unknown calibration method '" + std::string(name) + "' (use " + all + ")");
}

std::string_view method_name(Method method) {
  for (const auto& n : kNames)
    if (n.method == method) return n.name;
  return "unknown";
}

SpringModel calibrate(const mesh::Mesh& m, const std::vector<material::Material>& materials, Method method) {
  using mesh::ElementKind;
  if (materials.size() != 1 && materials.size() != static_cast<size_t>(m.element_count()))
    throw InvalidArgument("calibrate: give one material, or one per element");
  for (const auto& mat : materials) material::validate(mat);
  auto mat = [&](int e) -> const material::Material& {
    return materials.size() == 1 ? materials[0] : materials[static_cast<size_t>(e)];
  };
  const bool planar_tri = m.kind == ElementKind::kTriangle, quad = m.kind == ElementKind::kQuad,
             tet = m.kind == ElementKind::kTet;
  if (method == Method::kStiffnessFit) return stiffness_fit(m, materials);
  if (method == Method::kStiffnessFitVolume) return stiffness_fit(m, materials, {.volume_terms = true});
  detail::EdgeAccumulator acc(m);
  SpringModel out;
  switch (method) {
    case Method::kVanGelder:
      require_kind(m, planar_tri || tet, method, "triangles or tets");
      for (int e = 0; e < m.element_count(); ++e) {
        const double measure = mesh::element_measure(m, e) * (tet ? 1.0 : mat(e).thickness);
        acc.for_each_edge(e, [&](int s, double l) { acc.add(s, mat(e).youngs_modulus * measure / (l * l)); });
      }
      break;
    case Method::kLloydEquilateral:
      require_kind(m, planar_tri, method, "triangles");
      for (int e = 0; e < m.element_count(); ++e)
        acc.for_each_edge(
            e, [&](int s, double) { acc.add(s, mat(e).youngs_modulus * mat(e).thickness * std::sqrt(3.0) / 4.0); });
      break;
    case Method::kLloydTriangle:
      require_kind(m, planar_tri, method, "triangles");
      for (int e = 0; e < m.element_count(); ++e) {
        const double area = mesh::element_measure(m, e);
        acc.for_each_edge(e, [&](int s, double l) {
          const double a0 = std::sqrt(3.0) / 4.0 * l * l;  // equilateral triangle on this edge
          acc.add(s, mat(e).youngs_modulus * mat(e).thickness * std::sqrt(3.0) / 4.0 * area / a0);
        });
      }
      break;
    case Method::kLloydSquare:
      require_kind(m, quad, method, "quads");
      for (int e = 0; e < m.element_count(); ++e)
        acc.for_each_edge(e, [&](int s, double) {
          const double et = mat(e).youngs_modulus * mat(e).thickness;
          acc.add(s, acc.is_diagonal(s) ? 7.0 / 16.0 * et : 5.0 / 16.0 * et);
        });
      break;
    case Method::kLloydTet:
    case Method::kLloydTetVolume:
      require_kind(m, tet, method, "tets");
      for (int e = 0; e < m.element_count(); ++e) {
        const double lhat = equivalent_edge(mesh::element_measure(m, e));
        const double c =
            method == Method::kLloydTet ? 2.0 * std::sqrt(2.0) / 25.0 : 2.0 * std::sqrt(2.0) / 21.0 * 4.0 / 5.0;
        acc.for_each_edge(e, [&](int s, double) { acc.add(s, c * lhat * mat(e).youngs_modulus); });
      }
      break;
    case Method::kStiffnessFit:
    case Method::kStiffnessFitVolume: break;
  }
  out = acc.finish();
  if (method == Method::kLloydSquare)
    for (size_t s = 0; s < out.pairs.size(); ++s)
      out.rest_length(static_cast<Eigen::Index>(s)) *= acc.is_diagonal(static_cast<int>(s)) ? 6.0 / 7.0 : 6.0 / 5.0;
  if (method == Method::kLloydTetVolume) {
    out.volume_tets = m.elements;
    out.volume_stiffness.resize(m.element_count());
    out.rest_volume.resize(m.element_count());
    for (int e = 0; e < m.element_count(); ++e) {
      const double v = mesh::element_measure(m, e), lhat = equivalent_edge(v);
      out.rest_volume(e) = v;
      out.volume_stiffness(e) = std::sqrt(2.0) / 84.0 * lhat * lhat * lhat * mat(e).youngs_modulus * 2.0 / 5.0;
    }
  }
  return out;
}

}  // namespace hooke::calibrate
