#pragma once
/// The linear FEM's response to a load case at a given mean strain (the papers' "~12 % stretch", Lloyd et al. 2007
/// Sec. 5): the traction that produces it and the equilibrium under it, from one factorisation.
#include <hooke/material/material.hpp>
#include <hooke/mesh/mesh.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <vector>

namespace hooke::solve {

/// The traction (Pa) at which the linear FEM's mean top displacement along the load equals
/// strain x height (the papers' "~12 % stretch"). One linear solve with a unit traction, scaled.
/// @param materials  one material, or one per element (their law is ignored: the linear FEM decides)
/// @pre strain > 0
double traction_for_strain(const mesh::Mesh& mesh, const std::vector<material::Material>& materials,
                           model::LoadKind kind, double strain);

/// traction_for_strain's traction with the linear FEM's solution under it: the unit solve scaled by the traction
/// (the FEM is linear), so a comparison against the linear FEM at a strain costs one factorisation, not two.
struct StrainResponse {
  double traction_pa = 0.0;  ///< Pa
  StaticResult fem;          ///< positions (m) under traction_pa; the report's forces and residuals scaled with it
};
/// @pre strain > 0 @throws as traction_for_strain
StrainResponse linear_response_for_strain(const mesh::Mesh& mesh, const std::vector<material::Material>& materials,
                                          model::LoadKind kind, double strain);
/// linear_response_for_strain for each of `kinds` (which share their supports) from one factorisation.
/// @pre strain > 0 @throws as traction_for_strain
std::vector<StrainResponse> linear_responses_for_strain(const mesh::Mesh& mesh,
                                                        const std::vector<material::Material>& materials,
                                                        const std::vector<model::LoadKind>& kinds, double strain);

}  // namespace hooke::solve
