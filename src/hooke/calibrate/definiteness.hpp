#pragma once
/// Whether a tet spring model with volume terms resists every strain (docs/methods/any_nu.md). Negative volume
/// terms (k_V < 0, any-nu-tet and stiffness-fit-volume at nu < 1/4) can make the linearised stiffness indefinite.
#include <hooke/calibrate/spring_model.hpp>
#include <vector>

namespace hooke::calibrate {

/// Tets whose share of the linearised model is not positive definite on strains: for tet t,
/// S_t = sum_{s in t} w_st k_s l_s^2 n~_s n~_s^T + k_V,t m m^T (6 x 6, Mandel strains, N m), where n~_s is the
/// Mandel vector of n_s n_s^T, m = (1, 1, 1, 0, 0, 0), and spring s is shared among its tets in proportion to their
/// equivalent edge lengths (Lloyd Eq. 13; the split of Eq. 12). The assembled stiffness is sum_t B_t^T S_t B_t, so an
/// empty result proves it positive definite modulo rigid motions on a connected mesh (a sufficient condition).
/// @param mesh     validated tet mesh, positions in m
/// @param springs  springs on the edges of `mesh` (k in N/m), volume terms on its tets or none
/// @return indices of the failing tets, ascending (empty when every share is definite)
/// Springs on no tet of `mesh` are left out (they only add stiffness).
/// @throws InvalidArgument when `mesh` is not a tet mesh or the volume terms are not on its tets in its order
[[nodiscard]] std::vector<int> tets_without_definite_share(const mesh::Mesh& mesh, const SpringModel& springs);

}  // namespace hooke::calibrate
