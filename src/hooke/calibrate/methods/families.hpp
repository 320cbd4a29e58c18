#pragma once
// The method families (one file each in calibrate/methods/), as method_registry.cpp lists them, and what several
// share.
#include <cmath>
#include <hooke/calibrate/method_registry.hpp>
#include <vector>

namespace hooke::calibrate::methods {

std::vector<MethodEntry> van_gelder_methods();     // methods/van_gelder.cpp
std::vector<MethodEntry> lloyd_methods();          // methods/lloyd.cpp: Lloyd et al. 2007, Eq. 8-14
std::vector<MethodEntry> stiffness_fit_methods();  // methods/stiffness_fit_methods.cpp: Sec. 3.3 numerically
std::vector<MethodEntry> any_nu_methods();         // methods/any_nu.cpp: hooke's Cauchy split

/// The material of element e: the one given, or the e-th of one per element.
inline const material::Material& material_of(const std::vector<material::Material>& materials, int e) {
  return materials.size() == 1 ? materials[0] : materials[static_cast<size_t>(e)];
}
/// Equivalent edge length of a tet from its volume (Lloyd Eq. 13): V = l^3 sqrt(2) / 12.
inline double equivalent_edge(double volume) { return std::cbrt(volume * 12.0 / std::sqrt(2.0)); }

/// An entry with what every method has: its value, equation, the element kinds it takes (and their name for errors)
/// and its springs; where it is exact is left at "any nu, any shape".
inline MethodEntry method(Method value, std::string_view equation, bool (*takes)(const mesh::Mesh&),
                          std::string_view needs,
                          SpringModel (*springs)(const mesh::Mesh&, const std::vector<material::Material>&, Method)) {
  MethodEntry e;
  e.method = value;
  e.equation = equation;
  e.takes = takes;
  e.needs = needs;
  e.springs = springs;
  return e;
}

bool is_planar_triangles(const mesh::Mesh& m);
bool is_quads(const mesh::Mesh& m);
bool is_tets(const mesh::Mesh& m);

}  // namespace hooke::calibrate::methods
