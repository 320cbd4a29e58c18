#pragma once
/// Linear (Hookean) springs between node pairs, with optional prestrained rest lengths (Lloyd et al. 2007).
#include <array>
#include <hooke/core/element_schedule.hpp>
#include <hooke/model/term_block.hpp>
#include <vector>

namespace hooke::springs {

/// Energy of one spring: E = k/2 (|p_i - p_j| - l0)^2, J, with k in N/m and l0 in m.
/// @pre p_i != p_j
double spring_energy(const Eigen::Ref<const VecX>& pi, const Eigen::Ref<const VecX>& pj, double stiffness,
                     double rest_length);
/// dE/dp_i (N); dE/dp_j is its negative. This is the force the spring resists with at node i: the force it
/// applies to node i is the negative (Lloyd Sec. 3.2 prints the former as "the force at node i").
VecX spring_energy_gradient(const Eigen::Ref<const VecX>& pi, const Eigen::Ref<const VecX>& pj, double stiffness,
                            double rest_length);
/// d2E/dp_i2 (N/m), the d x d block A; the spring's Hessian is [A, -A; -A, A].
/// A = k [(1 - l0/l) I + (l0/l) u u^T] with l = |p_i - p_j|, u = (p_i - p_j)/l. At l = l0 this is Lloyd Eq. 6,
/// A = k/l0^2 (p_i - p_j)(p_i - p_j)^T; with prestrain (l0 = c |p_i - p_j|, Eq. 11) the isotropic term stays.
MatX spring_energy_hessian(const Eigen::Ref<const VecX>& pi, const Eigen::Ref<const VecX>& pj, double stiffness,
                           double rest_length);

/// Energy of one large-strain spring (docs/methods/large_strain.md): E = k l0^2 / 2 e_m(l / l0)^2, J, with the
/// Seth-Hill strain e_m(r) = (r^m - 1) / m (e_0 = ln r). m = 1 is the Hookean spring above; every m has the same
/// stiffness k at rest (Lloyd Eq. 6), and m < 1 stiffens the spring in compression (m <= 0: without bound as l -> 0).
/// @pre p_i != p_j, l0 > 0
double seth_hill_spring_energy(const Eigen::Ref<const VecX>& pi, const Eigen::Ref<const VecX>& pj, double stiffness,
                               double rest_length, double exponent);
/// dE/dp_i of seth_hill_spring_energy (N): k l0 g'(l / l0) (p_i - p_j) / l with g = e_m^2 / 2.
VecX seth_hill_spring_energy_gradient(const Eigen::Ref<const VecX>& pi, const Eigen::Ref<const VecX>& pj,
                                      double stiffness, double rest_length, double exponent);
/// d2E/dp_i2 of seth_hill_spring_energy (N/m): k g''(r) u u^T + k l0 g'(r) / l (I - u u^T), r = l / l0.
MatX seth_hill_spring_energy_hessian(const Eigen::Ref<const VecX>& pi, const Eigen::Ref<const VecX>& pj,
                                     double stiffness, double rest_length, double exponent);

/// All springs of a model, evaluated in one call.
class SpringBlock final : public model::TermBlock, public model::CentralSprings {
 public:
  /// @param dim           2 or 3
  /// @param pairs         node pairs (i, j), i != j
  /// @param stiffness     k per spring, N/m, >= 0
  /// @param rest_length   l0 per spring, m, > 0
  /// @param exponent      Seth-Hill exponent m of every spring (seth_hill_spring_energy), finite; 1 (default):
  ///                      Hookean springs
  /// @throws InvalidArgument on mismatched sizes, a negative stiffness, a non-positive rest length or a
  ///         non-finite exponent
  SpringBlock(int dim, std::vector<std::array<int, 2>> pairs, VecX stiffness, VecX rest_length, double exponent = 1.0);

  std::string_view name() const override { return "springs"; }
  /// Hookean springs only (exponent 1): the local/global split needs their quadratic energy.
  const model::CentralSprings* central_springs() const override { return m_exponent == 1.0 ? this : nullptr; }
  double energy(const Eigen::Ref<const VecX>& x) const override;
  void add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const override;
  double energy_and_add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const override;
  RowMatXi element_nodes() const override;
  /// With project_psd, the isotropic term k (1 - l0/l) I of a compressed spring (l < l0) is dropped, which
  /// leaves the closest positive semi-definite block of this form (for m != 1 each of the two terms is kept only
  /// where it is positive).
  void add_hessian_values(const Eigen::Ref<const VecX>& x, const model::HessianScatter& scatter, double* values,
                          bool project_psd) const override;

  /// Local step of Liu et al. 2013 (Fast Simulation of Mass-Spring Systems, Sec. 3): adds J d, i.e.
  /// k l0 (x_i - x_j)/|x_i - x_j| at node i and its negative at node j, N, to `out` (size of x). A spring of
  /// zero length adds nothing. Hookean springs only (exponent 1): the local/global split needs the quadratic
  /// energy.
  void add_rest_directions(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> out) const override;

  int dim() const { return m_dim; }
  const std::vector<std::array<int, 2>>& pairs() const override { return m_pairs; }
  const VecX& stiffness() const override { return m_stiffness; }
  const VecX& rest_length() const { return m_rest_length; }
  double exponent() const { return m_exponent; }

 private:
  int m_dim;
  double m_exponent = 1.0;
  std::vector<std::array<int, 2>> m_pairs;
  VecX m_stiffness;
  VecX m_rest_length;
  ElementSchedule m_schedule;
};

}  // namespace hooke::springs
