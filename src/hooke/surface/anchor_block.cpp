#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/name_table.hpp>
#include <hooke/surface/anchor_block.hpp>
#include <hooke/surface/normal_cone.hpp>

namespace hooke::surface {

namespace {
constexpr NameTable<AnchorLaw, 3> kAnchorLawNames{
    "anchor law", {{{AnchorLaw::kSingle, "single"}, {AnchorLaw::kBlend, "blend"}, {AnchorLaw::kTensor, "tensor"}}}};
}  // namespace

std::string_view anchor_law_name(AnchorLaw law) { return kAnchorLawNames.name(law); }
AnchorLaw anchor_law_from_name(std::string_view name) { return kAnchorLawNames.from_name(name); }

AnchorBlock::AnchorBlock(VecX anchors, const RowMatX& cones, VecX k_normal, VecX k_shear, AnchorLaw law)
    : m_anchors(std::move(anchors)), m_k_normal(std::move(k_normal)), m_k_shear(std::move(k_shear)), m_law(law) {
  const Eigen::Index n = m_anchors.size() / 3;
  if (m_anchors.size() != 3 * n || cones.rows() != n || cones.cols() != 6 || m_k_normal.size() != n ||
      m_k_shear.size() != n)
    throw InvalidArgument("AnchorBlock: one anchor, normal cone, K_E and K_G per node");
  m_cones.reserve(static_cast<size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) m_cones.push_back(unpack_cone(cones.row(i)));
  for (Eigen::Index i = 0; i < n; ++i)
    if (!(m_k_normal(i) >= 0.0) || !(m_k_shear(i) >= 0.0) || !std::isfinite(m_k_normal(i) + m_k_shear(i)))
      throw InvalidArgument("anchor " + std::to_string(i) + " has a negative or non-finite stiffness");
}

namespace {

// |c| = sqrt(q), q = d^T P d^, smoothed at c = 0 so that Newton's method does not stall on the kink of the paper's
// blend where a node moves along its tangent plane: (sqrt(q + s^2) - s) / (sqrt(1 + s^2) - s) is 0 at q = 0, 1 at
// q = 1 and within 0.01 of |c| everywhere.
constexpr double kSmoothing = 0.01;
const double kScale = std::sqrt(1.0 + kSmoothing * kSmoothing) - kSmoothing;
double blend_weight(double q) { return (std::sqrt(q + kSmoothing * kSmoothing) - kSmoothing) / kScale; }
// d(blend_weight)/dq times 2: the weight's gradient in d^ is (P d^) times this.
double blend_weight_slope(double q) { return 1.0 / (std::sqrt(q + kSmoothing * kSmoothing) * kScale); }

}  // namespace

double AnchorBlock::stiffness_along(int node, const Vec3& direction) const {
  if (m_law == AnchorLaw::kSingle) return m_k_normal(node);
  const Vec3 u = direction.normalized();
  const double q = u.dot(m_cones[static_cast<size_t>(node)] * u);
  const double w = m_law == AnchorLaw::kBlend ? blend_weight(q) : q;
  return w * m_k_normal(node) + (1.0 - w) * m_k_shear(node);
}

double AnchorBlock::energy(const Eigen::Ref<const VecX>& x) const {
  double e = 0.0;
  for (Eigen::Index i = 0; i < m_anchors.size() / 3; ++i) {
    const Vec3 d = x.segment<3>(3 * i) - m_anchors.segment<3>(3 * i);
    const double d2 = d.squaredNorm();
    if (d2 > 0.0) e += 0.5 * stiffness_along(static_cast<int>(i), d) * d2;
  }
  return e;
}

void AnchorBlock::add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
  for (Eigen::Index i = 0; i < m_anchors.size() / 3; ++i) {
    const Vec3 d = x.segment<3>(3 * i) - m_anchors.segment<3>(3 * i);
    if (m_law == AnchorLaw::kTensor) {
      gradient.segment<3>(3 * i) +=
          m_k_shear(i) * d + (m_k_normal(i) - m_k_shear(i)) * (m_cones[static_cast<size_t>(i)] * d);
    } else if (d.squaredNorm() > 0.0) {
      gradient.segment<3>(3 * i) += stiffness_along(static_cast<int>(i), d) * d;  // Eq. 2 with rest length 0
    }
  }
}

RowMatXi AnchorBlock::element_nodes() const {
  RowMatXi nodes(m_anchors.size() / 3, 1);
  for (Eigen::Index i = 0; i < nodes.rows(); ++i) nodes(i, 0) = static_cast<int>(i);
  return nodes;
}

void AnchorBlock::add_hessian_values(const Eigen::Ref<const VecX>& x, const model::HessianScatter& scatter,
                                     double* values, bool project_psd) const {
  for (Eigen::Index i = 0; i < m_anchors.size() / 3; ++i) {
    const Mat3& p = m_cones[static_cast<size_t>(i)];
    const Vec3 d = x.segment<3>(3 * i) - m_anchors.segment<3>(3 * i);
    Mat3 h = Mat3::Zero();
    switch (m_law) {
      case AnchorLaw::kSingle: h = m_k_normal(i) * Mat3::Identity(); break;
      case AnchorLaw::kTensor: h = m_k_shear(i) * Mat3::Identity() + (m_k_normal(i) - m_k_shear(i)) * p; break;
      case AnchorLaw::kBlend: {
        const double l = d.norm();
        if (l == 0.0) {
          h = m_k_normal(i) * Mat3::Identity();
          break;
        }
        const Vec3 u = d / l, pu = p * u;
        const double q = u.dot(pu);
        h = stiffness_along(static_cast<int>(i), d) * Mat3::Identity();
        if (!project_psd) {
          const Mat3 j = (m_k_normal(i) - m_k_shear(i)) * blend_weight_slope(q) * u * (pu - q * u).transpose();
          h += 0.5 * (j + j.transpose());
        }
        break;
      }
    }
    scatter.add<3, 1>(static_cast<int>(i), h, values);
  }
}

}  // namespace hooke::surface
