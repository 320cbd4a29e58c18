#include <cmath>
#include <hooke/calibrate/definiteness.hpp>
#include <hooke/calibrate/detail/mandel.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/symmetric_eigen.hpp>
#include <hooke/mesh/measure.hpp>
#include <map>

namespace hooke::calibrate {
namespace {

using detail::Mat6;
using detail::Vec6;

constexpr int kTetEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

}  // namespace

std::vector<int> tets_without_definite_share(const mesh::Mesh& m, const SpringModel& springs) {
  if (m.kind != mesh::ElementKind::kTet) throw InvalidArgument("the definiteness check needs a tet mesh");
  std::map<std::array<int, 2>, int> index;
  for (size_t s = 0; s < springs.pairs.size(); ++s)
    index[{std::min(springs.pairs[s][0], springs.pairs[s][1]), std::max(springs.pairs[s][0], springs.pairs[s][1])}] =
        static_cast<int>(s);
  std::vector<std::array<int, 6>> tet_springs(static_cast<size_t>(m.element_count()));
  VecX lhat(m.element_count()), share = VecX::Zero(static_cast<Eigen::Index>(springs.pairs.size()));
  for (int t = 0; t < m.element_count(); ++t) {
    lhat(t) = std::cbrt(mesh::element_measure(m, t) * 12.0 / std::sqrt(2.0));  // Eq. 13
    for (int k = 0; k < 6; ++k) {
      const int a = m.elements(t, kTetEdges[k][0]), b = m.elements(t, kTetEdges[k][1]);
      const auto it = index.find({std::min(a, b), std::max(a, b)});
      tet_springs[static_cast<size_t>(t)][static_cast<size_t>(k)] = it == index.end() ? -1 : it->second;
      if (it != index.end()) share(it->second) += lhat(t);
    }
  }
  std::vector<double> k_volume(static_cast<size_t>(m.element_count()), 0.0);
  for (Eigen::Index v = 0; v < springs.volume_tets.rows(); ++v) {
    // Volume terms are matched to the mesh's tets by their nodes in the mesh's order (as calibration writes them).
    if (v < m.element_count() && springs.volume_tets.row(v) == m.elements.row(v))
      k_volume[static_cast<size_t>(v)] += springs.volume_stiffness(v);
    else
      throw InvalidArgument("volume term " + std::to_string(v) + " is not on tet " + std::to_string(v) +
                            " of the mesh");
  }
  const Vec6 trace = detail::mandel_trace();
  std::vector<int> out;
  for (int t = 0; t < m.element_count(); ++t) {
    Mat6 s = k_volume[static_cast<size_t>(t)] * trace * trace.transpose();
    double scale = std::abs(k_volume[static_cast<size_t>(t)]);
    for (int k = 0; k < 6; ++k) {
      const int sp = tet_springs[static_cast<size_t>(t)][static_cast<size_t>(k)];
      if (sp < 0) continue;
      const Eigen::Vector3d d =
          (m.nodes.row(m.elements(t, kTetEdges[k][1])) - m.nodes.row(m.elements(t, kTetEdges[k][0]))).transpose();
      const double c = springs.stiffness(sp) * lhat(t) / share(sp) * d.squaredNorm();  // w_st k_s l_s^2
      const Vec6 n = detail::mandel_dyad(d.normalized());
      s += c * n * n.transpose();
      scale += std::abs(c);
    }
    // Definite with a margin of round-off: the smallest eigenvalue above 1e-12 of the entries' scale.
    if (!(symmetric_eigenvalues(s)(0) > 1e-12 * scale)) out.push_back(t);
  }
  return out;
}

}  // namespace hooke::calibrate
