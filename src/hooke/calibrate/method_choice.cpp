#include <algorithm>
#include <cmath>
#include <cstdio>
#include <hooke/calibrate/method_choice.hpp>
#include <hooke/core/error.hpp>
#include <map>
#include <sstream>

namespace hooke::calibrate {
namespace {

// A method's worst-case error at nu: linear between the two nearest tabulated nu, the nearest one outside the range.
// Negative when the method has no entry in the table.
double interpolated(const std::vector<const MeasuredError*>& entries, double nu) {
  if (entries.empty()) return -1.0;
  const MeasuredError* below = nullptr;
  const MeasuredError* above = nullptr;
  for (const MeasuredError* e : entries) {
    if (e->poisson <= nu && (!below || e->poisson > below->poisson)) below = e;
    if (e->poisson >= nu && (!above || e->poisson < above->poisson)) above = e;
  }
  if (!below) return above->worst_relative_l2;
  if (!above) return below->worst_relative_l2;
  if (above->poisson == below->poisson) return below->worst_relative_l2;
  const double s = (nu - below->poisson) / (above->poisson - below->poisson);
  return (1.0 - s) * below->worst_relative_l2 + s * above->worst_relative_l2;
}

std::string fixed3(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", x);
  return buf;
}

}  // namespace

const std::vector<MeasuredError>& measured_errors() {
  static const std::vector<MeasuredError> table = {
#include "method_table.inc"
  };
  return table;
}

std::string method_table_name(mesh::ElementKind kind, const material::Material& material) {
  if (kind == mesh::ElementKind::kTet) return "tet";
  if (kind == mesh::ElementKind::kTriangle)
    return material.plane == material::Plane::kStrain ? "triangle plane-strain" : "triangle plane-stress";
  return {};
}

MethodChoice choose_method(mesh::ElementKind kind, const material::Material& material,
                           const std::vector<MeasuredError>& table) {
  if (kind == mesh::ElementKind::kSurfaceTriangle) {
    MethodChoice tets = choose_method(mesh::ElementKind::kTet, material, table);
    tets.reason +=
        "; on the tets of the closed surface (mesh::tetrahedralize; --method surface gives Arnab & Raja's "
        "surface model of it instead)";
    return tets;
  }
  if (kind == mesh::ElementKind::kQuad)
    return {"stiffness-fit",
            "auto: stiffness-fit (quad meshes are not in the measured table; the per-element fit of the FEM stiffness "
            "is exact on the squares of Lloyd et al. Eq. 10-11 and the closest fit on other shapes)"};
  const std::string name = method_table_name(kind, material);
  const double nu = material.poisson_ratio;
  std::map<std::string, std::vector<const MeasuredError*>> by_method;
  std::vector<std::string> order;  // first appearance in the table
  for (const MeasuredError& e : table)
    if (e.table == name) {
      if (!by_method.count(e.method)) order.push_back(e.method);
      by_method[e.method].push_back(&e);
    }
  if (order.empty()) throw InvalidArgument("the method table has no entry for " + name + " meshes");
  // Errors within a relative 1e-6 of each other are ties (two methods that make the same springs on a mesh differ by
  // round-off only); a tie goes to the method that is best, or tied best, at more of the tabulated nu.
  const auto tied = [](double a, double best) { return a <= best * (1.0 + 1e-6); };
  std::map<double, double> best_at;
  for (const MeasuredError& e : table)
    if (e.table == name) {
      auto [it, fresh] = best_at.emplace(e.poisson, e.worst_relative_l2);
      if (!fresh) it->second = std::min(it->second, e.worst_relative_l2);
    }
  std::map<std::string, int> wins;
  for (const MeasuredError& e : table)
    if (e.table == name && tied(e.worst_relative_l2, best_at[e.poisson])) ++wins[e.method];
  std::vector<std::pair<double, std::string>> ranked;
  for (const std::string& method : order) ranked.emplace_back(interpolated(by_method[method], nu), method);
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  const double least = ranked.front().first;
  const auto ties_end =
      std::find_if(ranked.begin(), ranked.end(), [&](const auto& r) { return !tied(r.first, least); });
  std::stable_sort(ranked.begin(), ties_end,
                   [&](const auto& a, const auto& b) { return wins[a.second] > wins[b.second]; });
  // Where nu falls between two tabulated values, say so.
  double lo = -1.0, hi = 2.0;
  bool exact = false;
  for (const auto& entry : best_at) {
    const double p = entry.first;
    if (p == nu) exact = true;
    if (p <= nu) lo = std::max(lo, p);
    if (p >= nu) hi = std::min(hi, p);
  }
  std::ostringstream why;
  why << "auto: " << ranked.front().second << " (" << name << " meshes, nu = " << nu
      << "): the smallest worst-case relative L2 error against the linear FEM at small strain measured by the nu-range "
         "study (stretch, compression, shear";
  if (!exact)
    why << (lo < 0.0 || hi > 1.0 ? "; nu outside the measured range, its nearest value used"
                                 : "; interpolated between nu = " + fixed3(lo) + " and " + fixed3(hi));
  why << "): " << fixed3(ranked.front().first);
  for (std::size_t k = 1; k < ranked.size(); ++k)
    why << (k == 1 ? "; " : ", ") << ranked[k].second << " " << fixed3(ranked[k].first);
  return {ranked.front().second, why.str()};
}

std::string method_table_source(const std::vector<MeasuredError>& rows) {
  std::ostringstream o;
  o << "// Generated by `hooke reproduce nu-range` (method_table.inc in its output folder): per table, nu and method,\n"
       "// the worst relative L2 node error against the linear FEM at small strain over the study's meshes and loads,\n"
       "// and the number of cases. {table, nu, method, worst relative L2, cases}\n";
  for (const MeasuredError& e : rows) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", e.worst_relative_l2);
    o << "{\"" << e.table << "\", " << e.poisson << ", \"" << e.method << "\", " << buf << ", " << e.cases << "},\n";
  }
  return o.str();
}

}  // namespace hooke::calibrate
