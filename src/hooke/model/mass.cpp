#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/model/mass.hpp>

namespace hooke::model {

VecX lumped_masses(const mesh::Mesh& m, double density, double thickness) {
  if (!(density > 0.0) || !std::isfinite(density)) throw InvalidArgument("the density must be a positive number");
  const bool planar = m.kind != mesh::ElementKind::kTet;
  if (planar && (!(thickness > 0.0) || !std::isfinite(thickness)))
    throw InvalidArgument("the thickness must be a positive number");
  const int d = m.dim(), npe = static_cast<int>(m.elements.cols());
  VecX mass = VecX::Zero(m.nodes.size());
  for (int e = 0; e < m.element_count(); ++e) {
    const double share = density * std::abs(mesh::element_measure(m, e)) * (planar ? thickness : 1.0) / npe;
    for (int a = 0; a < npe; ++a) mass.segment(d * m.elements(e, a), d).array() += share;
  }
  return mass;
}

}  // namespace hooke::model
