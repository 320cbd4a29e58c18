#include <hooke/calibrate/cauchy_split.hpp>

namespace hooke::calibrate {

CauchySplit unclamped_cauchy_split(const material::Material& material) {
  const material::Lame l = material::lame(material.youngs_modulus, material.poisson_ratio);
  return {2.5 * l.mu, l.lambda - l.mu};
}

CauchySplit cauchy_split(const material::Material& material) {
  if (material.poisson_ratio < 0.25) return {material.youngs_modulus, 0.0};
  return unclamped_cauchy_split(material);
}

CauchySplit cauchy_split_2d(const material::Material& material) {
  const material::Lame l = material::lame(material, 2);
  if (l.lambda < l.mu) return {material.youngs_modulus, 0.0};
  return {8.0 / 3.0 * l.mu, l.lambda - l.mu};
}

}  // namespace hooke::calibrate
