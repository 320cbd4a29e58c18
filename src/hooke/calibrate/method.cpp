#include <cmath>
#include <cstdio>
#include <hooke/calibrate/cauchy_split.hpp>
#include <hooke/calibrate/detail/element_springs.hpp>
#include <hooke/calibrate/method.hpp>
#include <hooke/calibrate/stiffness_fit.hpp>
#include <hooke/calibrate/stiffness_scale.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/log.hpp>
#include <hooke/mesh/measure.hpp>

namespace hooke::calibrate {
namespace {

void require_kind(const mesh::Mesh& m, bool ok, Method method, const char* what) {
  if (!ok)
    throw InvalidArgument("method '" + std::string(method_name(method)) + "' needs " + what + ", not a " +
                          std::string(mesh::element_kind_name(m.kind)) + " mesh");
}

// Equivalent edge length of a tet from its volume (Eq. 13): V = l^3 sqrt(2)/12.
double equivalent_edge(double volume) { return std::cbrt(volume * 12.0 / std::sqrt(2.0)); }

std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

// Largest relative deviation of element e's edges (quads: sides, and the two diagonals from each other and
// from sqrt(2) times the side) from the regular shape's.
double irregularity(const mesh::Mesh& m, int e) {
  auto len = [&](int a, int b) { return (m.nodes.row(m.elements(e, a)) - m.nodes.row(m.elements(e, b))).norm(); };
  const int n = static_cast<int>(m.elements.cols());
  if (m.kind == mesh::ElementKind::kQuad) {
    const double side = 0.25 * (len(0, 1) + len(1, 2) + len(2, 3) + len(3, 0));
    double worst = 0.0;
    for (int a = 0; a < 4; ++a) worst = std::max(worst, std::abs(len(a, (a + 1) % 4) / side - 1.0));
    for (const auto& d : {len(0, 2), len(1, 3)}) worst = std::max(worst, std::abs(d / (std::sqrt(2.0) * side) - 1.0));
    return worst;
  }
  double lo = 1e300, hi = 0.0;
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      lo = std::min(lo, len(a, b));
      hi = std::max(hi, len(a, b));
    }
  return hi / lo - 1.0;
}

}  // namespace

std::vector<std::string> validity_warnings(const mesh::Mesh& m, const std::vector<material::Material>& materials,
                                           Method method) {
  std::vector<std::string> out;
  const std::string name(method_name(method));
  double exact_nu = -1.0;
  std::string eq;
  switch (method) {
    case Method::kLloydEquilateral: exact_nu = 1.0 / 3.0, eq = "Eq. 8"; break;
    case Method::kLloydTriangle: exact_nu = 1.0 / 3.0, eq = "Eq. 9"; break;
    case Method::kLloydSquare: exact_nu = 1.0 / 3.0, eq = "Eq. 10-11"; break;
    case Method::kLloydTet: exact_nu = 0.25, eq = "Eq. 12"; break;
    case Method::kLloydTetVolume: exact_nu = 0.25, eq = "Eq. 14"; break;
    default: return out;
  }
  const bool kind_ok = method == Method::kLloydSquare ? m.kind == mesh::ElementKind::kQuad
                       : exact_nu < 0.3               ? m.kind == mesh::ElementKind::kTet
                                                      : m.kind == mesh::ElementKind::kTriangle;
  if (!kind_ok) return out;  // calibrate() rejects the combination
  for (const auto& mat : materials)
    if (std::abs(mat.poisson_ratio - exact_nu) > 1e-9) {
      out.push_back(name + " (" + eq + ") is derived for nu = " + (exact_nu < 0.3 ? "1/4" : "1/3") + ", not " +
                    format_number(mat.poisson_ratio) +
                    ": the springs ignore nu and behave like that value (stiffness-fit gives the best fit at nu)");
      break;
    }
  if (method == Method::kLloydEquilateral || method == Method::kLloydSquare) {
    int worst = -1;
    double dev = 0.01;
    for (int e = 0; e < m.element_count(); ++e)
      if (const double d = irregularity(m, e); d > dev) dev = d, worst = e;
    if (worst >= 0)
      out.push_back(name + " (" + eq + ") is exact for " +
                    (method == Method::kLloydSquare ? "squares" : "equilateral triangles") + " only; " +
                    mesh::element_label(m, worst) + " deviates by " + std::to_string(static_cast<int>(100.0 * dev)) +
                    " % (use " +
                    (method == Method::kLloydSquare ? "stiffness-fit" : "lloyd-triangle or stiffness-fit") + ")");
  }
  return out;
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
  if (method == Method::kStiffnessFit || method == Method::kStiffnessFitVolume) {
    // Sec. 4.2.1 per element, then one factor on the springs from Eq. 1 under self-weight (stiffness_scale.hpp).
    const SpringModel fit = stiffness_fit(
        m, materials, {.volume = method == Method::kStiffnessFit ? VolumeTerm::kNone : VolumeTerm::kVolumetric});
    const StiffnessScale scale = fit_self_weight_scale(m, materials, fit);
    if (!scale.note.empty())
      log_warning(std::string(method_name(method)) + ": the fitted springs are left unscaled: " + scale.note);
    else
      log(LogLevel::kInfo, std::string(method_name(method)) + ": springs scaled by c = " +
                               std::to_string(scale.factor) + " (self-weight, Eq. 1; relative error " +
                               std::to_string(scale.error_before) + " -> " + std::to_string(scale.error_after) + ")");
    return with_scaled_springs(fit, scale.factor);
  }
  if (m.kind == mesh::ElementKind::kTriangle || m.kind == mesh::ElementKind::kQuad || m.kind == mesh::ElementKind::kTet)
    for (const auto& w : validity_warnings(m, materials, method)) log_warning(w);
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
    case Method::kAnyNuTriangle:
      require_kind(m, planar_tri, method, "triangles");
      for (int e = 0; e < m.element_count(); ++e) {
        const double area = mesh::element_measure(m, e);
        // any-nu-triangle: Eq. 9 at E_s = 8 mu / 3, the nu = 1/3 material carrying the shear modulus (cauchy_split_2d)
        const double es =
            method == Method::kAnyNuTriangle ? cauchy_split_2d(mat(e)).spring_youngs_modulus : mat(e).youngs_modulus;
        acc.for_each_edge(e, [&](int s, double l) {
          const double a0 = std::sqrt(3.0) / 4.0 * l * l;  // equilateral triangle on this edge
          acc.add(s, es * mat(e).thickness * std::sqrt(3.0) / 4.0 * area / a0);
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
    case Method::kAnyNuTet:
      require_kind(m, tet, method, "tets");
      for (int e = 0; e < m.element_count(); ++e) {
        const double lhat = equivalent_edge(mesh::element_measure(m, e));
        const double es = cauchy_split(mat(e)).spring_youngs_modulus;  // Eq. 12 at E_s
        acc.for_each_edge(e, [&](int s, double) { acc.add(s, 2.0 * std::sqrt(2.0) / 25.0 * lhat * es); });
      }
      break;
    case Method::kStiffnessFit:
    case Method::kStiffnessFitVolume: break;
  }
  out = acc.finish();
  if (method == Method::kLloydSquare)
    for (size_t s = 0; s < out.pairs.size(); ++s)
      out.rest_length(static_cast<Eigen::Index>(s)) *= acc.is_diagonal(static_cast<int>(s)) ? 6.0 / 7.0 : 6.0 / 5.0;
  if (method == Method::kLloydTetVolume || method == Method::kAnyNuTet) {
    out.volume_tets = m.elements;
    out.volume_stiffness.resize(m.element_count());
    out.rest_volume.resize(m.element_count());
    for (int e = 0; e < m.element_count(); ++e) {
      const double v = mesh::element_measure(m, e), lhat = equivalent_edge(v);
      out.rest_volume(e) = v;
      out.volume_stiffness(e) =
          method == Method::kAnyNuTet
              ? cauchy_split(mat(e)).volume_lambda * v  // linearises to lambda_V V0 (tr eps)^2 / 2
              : std::sqrt(2.0) / 84.0 * lhat * lhat * lhat * mat(e).youngs_modulus * 2.0 / 5.0;
    }
  }
  if (method == Method::kAnyNuTriangle) {  // area terms k_A = lambda_A t A0: (A - A0)/A0 = tr eps to first order
    out.volume_tets = m.elements;
    out.volume_stiffness.resize(m.element_count());
    out.rest_volume.resize(m.element_count());
    for (int e = 0; e < m.element_count(); ++e) {
      out.rest_volume(e) = mesh::element_measure(m, e);
      out.volume_stiffness(e) = cauchy_split_2d(mat(e)).volume_lambda * mat(e).thickness * out.rest_volume(e);
    }
  }
  if ((method == Method::kAnyNuTet || method == Method::kAnyNuTriangle) && out.volume_stiffness.isZero(0.0)) {
    // nu <= 1/4 (tets) or lambda* <= mu (triangles): springs only, lloyd-tet or lloyd-triangle
    out.volume_tets.resize(0, m.elements.cols());
    out.volume_stiffness.resize(0);
    out.rest_volume.resize(0);
  }
  return out;
}

}  // namespace hooke::calibrate
