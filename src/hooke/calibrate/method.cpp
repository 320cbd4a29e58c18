#include <cmath>
#include <cstdio>
#include <hooke/calibrate/method.hpp>
#include <hooke/calibrate/method_registry.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/log.hpp>
#include <hooke/mesh/measure.hpp>

namespace hooke::calibrate {
namespace {

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
  const MethodEntry& entry = method_entry(method);
  if (entry.exact_nu < 0.0 || !entry.takes(m)) return out;  // exact at any nu, or refused by calibrate()
  const std::string name(method_name(method)), eq(entry.exact_equation);
  for (const auto& mat : materials)
    if (std::abs(mat.poisson_ratio - entry.exact_nu) > 1e-9) {
      out.push_back(name + " (" + eq + ") is derived for nu = " + std::string(entry.exact_nu_text) + ", not " +
                    format_number(mat.poisson_ratio) +
                    ": the springs ignore nu and behave like that value (stiffness-fit gives the best fit at nu)");
      break;
    }
  if (!entry.regular_shape.empty()) {
    int worst = -1;
    double dev = 0.01;
    for (int e = 0; e < m.element_count(); ++e)
      if (const double d = irregularity(m, e); d > dev) dev = d, worst = e;
    if (worst >= 0)
      out.push_back(name + " (" + eq + ") is exact for " + std::string(entry.regular_shape) + " only; " +
                    mesh::element_label(m, worst) + " deviates by " + std::to_string(static_cast<int>(100.0 * dev)) +
                    " % (use " + std::string(entry.instead) + ")");
  }
  return out;
}

SpringModel calibrate(const mesh::Mesh& m, const std::vector<material::Material>& materials, Method method) {
  if (materials.size() != 1 && materials.size() != static_cast<size_t>(m.element_count()))
    throw InvalidArgument("calibrate: give one material, or one per element");
  for (const auto& mat : materials) material::validate(mat);
  const MethodEntry& entry = method_entry(method);  // its family's file in calibrate/methods/
  for (const auto& w : validity_warnings(m, materials, method)) log_warning(w);
  if (!entry.takes(m))
    throw InvalidArgument("method '" + std::string(method_name(method)) + "' needs " + std::string(entry.needs) +
                          ", not a " + std::string(mesh::element_kind_name(m.kind)) + " mesh");
  return entry.springs(m, materials, method);
}

}  // namespace hooke::calibrate
