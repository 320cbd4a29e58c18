#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/name_table.hpp>
#include <hooke/mesh/closed_surface.hpp>
#include <hooke/surface/volume_penalty_block.hpp>
#include <numbers>
#include <vector>

namespace hooke::surface {
namespace {

using Mat3 = Eigen::Matrix<double, 3, 3>;

Mat3 cross_matrix(const Vec3& v) {
  Mat3 m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

// g = dV/dx (V = sum over triangles of a . (b x c) / 6) into `g`, and the area-weighted node normals (not
// normalised) into `normals` (3 per node); returns V.
double volume_and_gradient(const RowMatXi& tri, const Eigen::Ref<const VecX>& x, VecX& g, VecX& normals) {
  g.setZero(x.size());
  normals.setZero(x.size());
  double v = 0.0;
  for (Eigen::Index t = 0; t < tri.rows(); ++t) {
    const int i = tri(t, 0), j = tri(t, 1), k = tri(t, 2);
    const Vec3 a = x.segment<3>(3 * i), b = x.segment<3>(3 * j), c = x.segment<3>(3 * k);
    v += a.dot(b.cross(c)) / 6.0;
    g.segment<3>(3 * i) += b.cross(c) / 6.0;
    g.segment<3>(3 * j) += c.cross(a) / 6.0;
    g.segment<3>(3 * k) += a.cross(b) / 6.0;
    const Vec3 n = (b - a).cross(c - a);
    normals.segment<3>(3 * i) += n;
    normals.segment<3>(3 * j) += n;
    normals.segment<3>(3 * k) += n;
  }
  return v;
}

// Work vectors of one evaluation, per thread (a block is shared by threads and must not hold them); sized at the
// first evaluation of a block of this size on the thread, allocation-free after.
struct Scratch {
  VecX volume_gradient, weights, normals;
  std::vector<char> done;
};

Scratch& scratch(Eigen::Index nodes) {
  thread_local Scratch s;
  if (s.weights.size() != nodes) {
    s.volume_gradient.setZero(3 * nodes);
    s.normals.setZero(3 * nodes);
    s.weights.setOnes(nodes);
    s.done.assign(static_cast<size_t>(nodes), 0);
  }
  return s;
}

void fill_weights(const Eigen::Ref<const VecX>& x, const Interaction& in, VecX& w) {
  const Eigen::Index n = x.size() / 3;
  w.setZero(n);
  const Vec3 f = in.direction.normalized();
  double sum = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Vec3 r = x.segment<3>(3 * i) - in.point;
    const double dist = r.norm();
    if (dist == 0.0 || dist >= in.radius) continue;
    const double wi = (r / dist).dot(f) * std::cos(std::numbers::pi * dist / (2.0 * in.radius));
    if (wi > 0.0) {
      w(i) = wi;
      sum += wi;
    }
  }
  if (sum > 0.0)
    w *= static_cast<double>(n) / sum;
  else
    w.setOnes(n);
}

}  // namespace

namespace {
constexpr NameTable<VolumeForce, 3> kVolumeForceNames{
    "volume force",
    {{{VolumeForce::kNodal, "nodal"}, {VolumeForce::kPrinted, "printed"}, {VolumeForce::kEnergy, "energy"}}}};
}  // namespace

std::string_view volume_force_name(VolumeForce force) { return kVolumeForceNames.name(force); }
VolumeForce volume_force_from_name(std::string_view name) { return kVolumeForceNames.from_name(name); }

VecX interaction_weights(const Eigen::Ref<const VecX>& x, const Interaction& interaction) {
  model::require_valid(interaction);
  VecX w;
  fill_weights(x, interaction, w);
  return w;
}

VolumePenaltyBlock::VolumePenaltyBlock(RowMatXi triangles, double rest_volume, VecX k_bulk, VecX normal_length,
                                       double bulk_modulus, VolumeForce force)
    : m_triangles(std::move(triangles)),
      m_rest_volume(rest_volume),
      m_bulk_modulus(bulk_modulus),
      m_k_bulk(std::move(k_bulk)),
      m_normal_length(std::move(normal_length)),
      m_force(force) {
  if (!(rest_volume > 0.0)) throw InvalidArgument("VolumePenaltyBlock: the rest volume must be positive");
  if (!(bulk_modulus > 0.0)) throw InvalidArgument("VolumePenaltyBlock: the bulk modulus must be positive");
  if (m_k_bulk.size() != m_normal_length.size())
    throw InvalidArgument("VolumePenaltyBlock: one K_B and one L' per node");
}

VecX VolumePenaltyBlock::weights(const Eigen::Ref<const VecX>& x, const Interaction* interaction) const {
  if (!interaction) return VecX::Ones(x.size() / 3);
  return interaction_weights(x, *interaction);
}

double VolumePenaltyBlock::energy(const Eigen::Ref<const VecX>& x) const {
  const double dv = mesh::enclosed_volume(m_triangles, x) - m_rest_volume;
  return 0.5 * m_bulk_modulus * dv * dv / m_rest_volume;
}

void VolumePenaltyBlock::add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
  add_forces(x, nullptr, gradient);
}

void VolumePenaltyBlock::add_interaction_gradient(const Eigen::Ref<const VecX>& x, const Interaction& interaction,
                                                  Eigen::Ref<VecX> gradient) const {
  add_forces(x, &interaction, gradient);
}

void VolumePenaltyBlock::add_forces(const Eigen::Ref<const VecX>& x, const Interaction* interaction,
                                    Eigen::Ref<VecX> gradient) const {
  Scratch& w = scratch(m_k_bulk.size());
  VecX& g = w.volume_gradient;
  const double v = volume_and_gradient(m_triangles, x, g, w.normals);
  const VecX& normals = w.normals;
  const double lost = m_rest_volume - v;
  if (m_force == VolumeForce::kEnergy) {
    gradient -= (m_bulk_modulus * lost / m_rest_volume) * g;  // force +K (V0 - V)/V0 dV/dx
    return;
  }
  if (interaction) fill_weights(x, *interaction, w.weights);
  const double scale = m_force == VolumeForce::kNodal ? lost / m_rest_volume : lost;
  for (Eigen::Index i = 0; i < m_k_bulk.size(); ++i) {
    Vec3 dir;
    if (interaction) {
      dir = x.segment<3>(3 * i) - interaction->point;
      const double l = dir.norm();
      if (l == 0.0) continue;
      dir /= l;
    } else {
      dir = normals.segment<3>(3 * i).normalized();
    }
    const double k = m_force == VolumeForce::kNodal ? m_k_bulk(i) * m_normal_length(i) : m_k_bulk(i);
    gradient.segment<3>(3 * i) -= (k * scale * (interaction ? w.weights(i) : 1.0)) * dir;
  }
}

RowMatXi VolumePenaltyBlock::element_nodes() const { return m_triangles; }

void VolumePenaltyBlock::add_hessian_values(const Eigen::Ref<const VecX>& x, const model::HessianScatter& scatter,
                                            double* values, bool project_psd) const {
  add_stiffness(x, nullptr, scatter, values, project_psd);
}

void VolumePenaltyBlock::add_interaction_hessian_values(const Eigen::Ref<const VecX>& x, const Interaction& interaction,
                                                        const model::HessianScatter& scatter, double* values,
                                                        bool project_psd) const {
  add_stiffness(x, &interaction, scatter, values, project_psd);
}

void VolumePenaltyBlock::add_stiffness(const Eigen::Ref<const VecX>& x, const Interaction* interaction,
                                       const model::HessianScatter& scatter, double* values, bool project_psd) const {
  Scratch& w = scratch(m_k_bulk.size());
  VecX& g = w.volume_gradient;
  const double v = volume_and_gradient(m_triangles, x, g, w.normals);
  if (interaction) fill_weights(x, *interaction, w.weights);
  // Node-diagonal blocks of the rank-one stiffness, added once per node through its first triangle.
  std::vector<char>& done = w.done;
  std::fill(done.begin(), done.end(), 0);
  const double pressure = m_bulk_modulus * (v - m_rest_volume) / m_rest_volume;
  Eigen::Matrix<double, 9, 9> h;
  for (Eigen::Index t = 0; t < m_triangles.rows(); ++t) {
    h.setZero();
    for (int a = 0; a < 3; ++a) {
      const int i = m_triangles(t, a);
      if (done[static_cast<size_t>(i)]) continue;
      done[static_cast<size_t>(i)] = 1;
      const Vec3 gi = g.segment<3>(3 * i);
      double k = m_bulk_modulus / m_rest_volume;  // kEnergy: K/V0 g_i g_i^T
      if (m_force != VolumeForce::kEnergy) {
        // d|F_i|/dV = K_B,i L'_i w_i / V0 (nodal) or K_B,i w_i (printed), along N_i ~ g_i/|g_i|: the same
        // rank-one form with this coefficient.
        const double kb =
            m_force == VolumeForce::kNodal ? m_k_bulk(i) * m_normal_length(i) / m_rest_volume : m_k_bulk(i);
        k = kb * (interaction ? w.weights(i) : 1.0) / std::max(gi.norm(), 1e-300);
      }
      h.block<3, 3>(3 * a, 3 * a) += k * gi * gi.transpose();
    }
    if (m_force == VolumeForce::kEnergy && !project_psd) {
      const Vec3 p = x.segment<3>(3 * m_triangles(t, 0)), q = x.segment<3>(3 * m_triangles(t, 1)),
                 r = x.segment<3>(3 * m_triangles(t, 2));
      // d2V/dadb = -[c]x/6 and cyclic (V = a . (b x c) / 6).
      const Mat3 ab = -cross_matrix(r) / 6.0, bc = -cross_matrix(p) / 6.0, ca = -cross_matrix(q) / 6.0;
      h.block<3, 3>(0, 3) += pressure * ab;
      h.block<3, 3>(3, 0) += pressure * ab.transpose();
      h.block<3, 3>(3, 6) += pressure * bc;
      h.block<3, 3>(6, 3) += pressure * bc.transpose();
      h.block<3, 3>(6, 0) += pressure * ca;
      h.block<3, 3>(0, 6) += pressure * ca.transpose();
    }
    scatter.add<3, 3>(static_cast<int>(t), h, values);
  }
}

}  // namespace hooke::surface
