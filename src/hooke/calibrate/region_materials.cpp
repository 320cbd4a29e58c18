#include <algorithm>
#include <cmath>
#include <cstdio>
#include <hooke/calibrate/region_materials.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/settings.hpp>
#include <map>

namespace hooke::calibrate {

RegionMaterial parse_region_material(std::string_view text) {
  const std::string where = "--material '" + std::string(text) + "'";
  const std::size_t equals = text.find('='), comma = text.find(',');
  if (equals == std::string_view::npos || comma == std::string_view::npos || comma < equals)
    throw InvalidArgument(where + ": expected REGION=E,NU (a region tag, Young's modulus in Pa, Poisson's ratio)");
  RegionMaterial r;
  r.region = settings::parse_integer(where + " region", text.substr(0, equals));
  r.youngs_modulus = settings::parse_number(where + " E", text.substr(equals + 1, comma - equals - 1));
  r.poisson_ratio = settings::parse_number(where + " nu", text.substr(comma + 1));
  validate_regions({r});
  return r;
}

void validate_regions(const std::vector<RegionMaterial>& regions) {
  std::map<int, int> seen;
  for (const RegionMaterial& r : regions) {
    material::Material m;
    m.youngs_modulus = r.youngs_modulus;
    m.poisson_ratio = r.poisson_ratio;
    try {
      material::validate(m);
    } catch (const InvalidMaterial& e) {
      throw InvalidMaterial("region " + std::to_string(r.region) + ": " + e.what());
    }
    if (++seen[r.region] > 1) throw InvalidArgument("region " + std::to_string(r.region) + " is given two materials");
  }
}

std::string describe_regions(const mesh::Mesh& mesh) {
  std::map<int, int> count;
  for (Eigen::Index e = 0; e < mesh.region.size(); ++e) ++count[mesh.region(e)];
  const std::string kind(mesh::element_kind_name(mesh.kind));
  std::string out;
  for (const auto& [tag, n] : count)
    out += (out.empty() ? "" : ", ") + std::to_string(tag) + " (" + std::to_string(n) + " " + kind + "s)";
  return out.empty() ? "none" : out;
}

std::vector<material::Material> element_materials(const mesh::Mesh& mesh, const material::Material& base,
                                                  const std::vector<RegionMaterial>& regions, bool require_all) {
  if (regions.empty()) return {base};
  validate_regions(regions);
  const int ne = mesh.element_count();
  if (mesh.region.size() != ne)
    throw InvalidArgument(mesh.source + ": the mesh has no element regions, so --material REGION=E,NU cannot apply");
  std::map<int, const RegionMaterial*> by_tag;
  for (const RegionMaterial& r : regions) by_tag[r.region] = &r;
  std::map<int, int> used, unlisted;
  std::vector<material::Material> out(static_cast<std::size_t>(ne), base);
  for (int e = 0; e < ne; ++e) {
    const auto it = by_tag.find(mesh.region(e));
    if (it == by_tag.end()) {
      ++unlisted[mesh.region(e)];
      continue;
    }
    ++used[it->first];
    out[static_cast<std::size_t>(e)].youngs_modulus = it->second->youngs_modulus;
    out[static_cast<std::size_t>(e)].poisson_ratio = it->second->poisson_ratio;
  }
  for (const RegionMaterial& r : regions)
    if (!used.count(r.region))
      throw InvalidArgument(mesh.source + " has no element in region " + std::to_string(r.region) +
                            " (its regions: " + describe_regions(mesh) + ")");
  if (require_all && !unlisted.empty())
    throw InvalidArgument(mesh.source + ": region " + std::to_string(unlisted.begin()->first) + " (" +
                          std::to_string(unlisted.begin()->second) +
                          " elements) has no material: give --material for it, or --young and --poisson for the rest");
  return out;
}

std::vector<std::string> describe_region_materials(const mesh::Mesh& mesh, const material::Material& base,
                                                   const std::vector<RegionMaterial>& regions) {
  std::map<int, int> count;
  for (Eigen::Index e = 0; e < mesh.region.size(); ++e) ++count[mesh.region(e)];
  const std::string kind(mesh::element_kind_name(mesh.kind));
  std::vector<std::string> out;
  char line[192];
  int listed = 0;
  for (const RegionMaterial& r : regions) {
    const int n = count.count(r.region) ? count[r.region] : 0;
    listed += n;
    std::snprintf(line, sizeof line, "region %d: E %.6g Pa, nu %.4g, %d %ss", r.region, r.youngs_modulus,
                  r.poisson_ratio, n, kind.c_str());
    out.emplace_back(line);
  }
  if (listed < mesh.element_count()) {
    std::snprintf(line, sizeof line, "%s: E %.6g Pa, nu %.4g, %d %ss", regions.empty() ? "all" : "other regions",
                  base.youngs_modulus, base.poisson_ratio, mesh.element_count() - listed, kind.c_str());
    out.emplace_back(line);
  }
  return out;
}

std::pair<double, double> unlisted_elasticity(const mesh::Mesh& mesh, const std::vector<RegionMaterial>& regions,
                                              double youngs_modulus, double poisson_ratio) {
  const bool e = !std::isnan(youngs_modulus), nu = !std::isnan(poisson_ratio);
  if (e && nu) return {youngs_modulus, poisson_ratio};
  if (e || nu) throw InvalidArgument("give both --young and --poisson (the material of the regions not listed)");
  if (regions.empty()) throw InvalidArgument("--young and --poisson are required (or --material REGION=E,NU)");
  material::Material first;
  first.youngs_modulus = regions.front().youngs_modulus;
  first.poisson_ratio = regions.front().poisson_ratio;
  element_materials(mesh, first, regions, true);  // every element in a listed region
  return {first.youngs_modulus, first.poisson_ratio};
}

}  // namespace hooke::calibrate
