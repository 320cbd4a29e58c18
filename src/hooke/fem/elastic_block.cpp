#include <cmath>
#include <hooke/core/detail/psd.hpp>
#include <hooke/core/error.hpp>
#include <hooke/fem/detail/elastic_kernel.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/fem/quad4.hpp>
#include <hooke/fem/tet4.hpp>
#include <limits>

namespace hooke::fem {
namespace {

using mesh::ElementKind;

template <int D, int N>
detail::Positions<D, N> gather(const Eigen::Ref<const VecX>& x, const RowMatXi& elements, int e) {
  detail::Positions<D, N> p;
  for (int a = 0; a < N; ++a)
    for (int i = 0; i < D; ++i) p(a, i) = x(D * elements(e, a) + i);
  return p;
}

// Evaluates the requested derivatives of element e; returns false where the energy is infinite.
template <int D, int N>
bool evaluate(const std::vector<int>& first, const std::vector<double>& weight, const std::vector<double>& grad,
              material::Law law, const material::Lame& lame, const detail::Positions<D, N>& p, int e, double* energy,
              detail::ElementVector<D, N>* gradient, detail::ElementMatrix<D, N>* hessian) {
  for (int q = first[static_cast<size_t>(e)]; q < first[static_cast<size_t>(e) + 1]; ++q) {
    const Eigen::Map<const Eigen::Matrix<double, N, D, Eigen::RowMajor>> dn(&grad[static_cast<size_t>(q) * N * D]);
    if (!detail::add_quadrature_point<D, N>(law, lame, weight[static_cast<size_t>(q)], p, dn, energy, gradient,
                                            hessian))
      return false;
  }
  return true;
}

}  // namespace

ElasticBlock::ElasticBlock(const mesh::Mesh& mesh, const std::vector<material::Material>& materials)
    : m_kind(mesh.kind), m_dim(mesh.dim()), m_npe(mesh::nodes_per_element(mesh.kind)), m_elements(mesh.elements) {
  if (mesh.kind == ElementKind::kSurfaceTriangle)
    throw InvalidArgument("FEM needs a planar (triangle, quad) or volume (tet) mesh, not a surface mesh");
  const int ne = mesh.element_count();
  if (materials.size() != 1 && materials.size() != static_cast<size_t>(ne))
    throw InvalidArgument("ElasticBlock: give one material, or one per element");
  m_law.reserve(static_cast<size_t>(ne));
  m_lame.reserve(static_cast<size_t>(ne));
  m_first_point.push_back(0);
  for (int e = 0; e < ne; ++e) {
    const material::Material& mat = materials.size() == 1 ? materials[0] : materials[static_cast<size_t>(e)];
    material::validate(mat);
    m_law.push_back(mat.law);
    m_lame.push_back(material::lame(mat, m_dim));
    const double t = m_dim == 2 ? mat.thickness : 1.0;
    auto fail = [&] { throw InvalidMesh(mesh::element_label(mesh, e) + " has a non-positive Jacobian", e); };
    if (m_kind == ElementKind::kTet) {
      Eigen::Matrix<double, 4, 3> nodes, dn;
      for (int a = 0; a < 4; ++a) nodes.row(a) = mesh.nodes.row(mesh.elements(e, a));
      const double v = tet4_gradients(nodes, dn);
      if (!(v > 0.0)) fail();
      m_weight.push_back(v);
      for (int a = 0; a < 4; ++a)
        for (int c = 0; c < 3; ++c) m_grad.push_back(dn(a, c));
    } else if (m_kind == ElementKind::kTriangle) {
      Mat2 edges;
      const Vec2 p0 = mesh.nodes.row(mesh.elements(e, 0)).transpose();
      edges.col(0) = mesh.nodes.row(mesh.elements(e, 1)).transpose() - p0;
      edges.col(1) = mesh.nodes.row(mesh.elements(e, 2)).transpose() - p0;
      const double area = 0.5 * edges.determinant();
      if (!(area > 0.0)) fail();
      // N1 = 1 - s - r, N2 = s, N3 = r with (s, r) = edges^-1 (X - p0).
      const Mat2 inv = edges.inverse();
      Eigen::Matrix<double, 3, 2> dn;
      dn.row(1) = inv.row(0);
      dn.row(2) = inv.row(1);
      dn.row(0) = -dn.row(1) - dn.row(2);
      m_weight.push_back(area * t);
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 2; ++c) m_grad.push_back(dn(a, c));
    } else {
      Eigen::Matrix<double, 4, 2> nodes, dn;
      for (int a = 0; a < 4; ++a) nodes.row(a) = mesh.nodes.row(mesh.elements(e, a));
      const double g = 1.0 / std::sqrt(3.0);
      for (double xi : {-g, g})
        for (double eta : {-g, g}) {
          const double det = quad4_gradients(nodes, xi, eta, dn);
          if (!(det > 0.0)) fail();
          m_weight.push_back(det * t);
          for (int a = 0; a < 4; ++a)
            for (int c = 0; c < 2; ++c) m_grad.push_back(dn(a, c));
        }
    }
    m_first_point.push_back(static_cast<int>(m_weight.size()));
  }
  m_schedule = ElementSchedule(m_elements);
}

// Calls fn(integral_constant<D>, integral_constant<N>) for the block's element kind.
template <typename Fn>
void dispatch(ElementKind kind, Fn&& fn) {
  using std::integral_constant;
  if (kind == ElementKind::kTet) {
    fn(integral_constant<int, 3>{}, integral_constant<int, 4>{});
  } else if (kind == ElementKind::kTriangle) {
    fn(integral_constant<int, 2>{}, integral_constant<int, 3>{});
  } else {
    fn(integral_constant<int, 2>{}, integral_constant<int, 4>{});
  }
}

bool ElasticBlock::element_terms(const Eigen::Ref<const VecX>& x, int e, double* energy, VecX* gradient,
                                 MatX* hessian) const {
  bool finite = true;
  dispatch(m_kind, [&](auto d, auto n) {
    constexpr int D = decltype(d)::value, N = decltype(n)::value;
    const auto p = gather<D, N>(x, m_elements, e);
    detail::ElementVector<D, N> g = detail::ElementVector<D, N>::Zero();
    detail::ElementMatrix<D, N> h = detail::ElementMatrix<D, N>::Zero();
    const auto se = static_cast<size_t>(e);
    finite = evaluate<D, N>(m_first_point, m_weight, m_grad, m_law[se], m_lame[se], p, e, energy,
                            gradient ? &g : nullptr, hessian ? &h : nullptr);
    if (gradient) *gradient = g;
    if (hessian) *hessian = h;
  });
  return finite;
}

double ElasticBlock::energy(const Eigen::Ref<const VecX>& x) const {
  return m_schedule.sum([&](int e) {
    double energy = 0.0;
    return element_terms(x, e, &energy, nullptr, nullptr) ? energy : std::numeric_limits<double>::infinity();
  });
}

void ElasticBlock::add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const {
  dispatch(m_kind, [&](auto d, auto n) {
    constexpr int D = decltype(d)::value, N = decltype(n)::value;
    m_schedule.for_each_chunk([&](std::span<const int> elements, int) {
      for (int e : elements) {
        detail::ElementVector<D, N> g = detail::ElementVector<D, N>::Zero();
        const auto se = static_cast<size_t>(e);
        evaluate<D, N>(m_first_point, m_weight, m_grad, m_law[se], m_lame[se], gather<D, N>(x, m_elements, e), e,
                       nullptr, &g, nullptr);
        for (int a = 0; a < N; ++a) gradient.segment<D>(D * m_elements(e, a)) += g.template segment<D>(D * a);
      }
    });
  });
}

void ElasticBlock::add_hessian_values(const Eigen::Ref<const VecX>& x, const model::HessianScatter& scatter,
                                      double* values, bool project_psd) const {
  dispatch(m_kind, [&](auto d, auto n) {
    constexpr int D = decltype(d)::value, N = decltype(n)::value;
    m_schedule.for_each_chunk([&](std::span<const int> elements, int) {
      for (int e : elements) {
        detail::ElementMatrix<D, N> h = detail::ElementMatrix<D, N>::Zero();
        const auto se = static_cast<size_t>(e);
        evaluate<D, N>(m_first_point, m_weight, m_grad, m_law[se], m_lame[se], gather<D, N>(x, m_elements, e), e,
                       nullptr, nullptr, &h);
        if (project_psd) hooke::detail::project_to_psd(h);
        scatter.add<D, N>(e, h, values);
      }
    });
  });
}

void ElasticBlock::element_derivatives(const Eigen::Ref<const VecX>& x, int e, double& energy, VecX& gradient,
                                       MatX& hessian) const {
  energy = 0.0;
  if (!element_terms(x, e, &energy, &gradient, &hessian)) energy = std::numeric_limits<double>::infinity();
}

std::unique_ptr<ElasticBlock> make_elastic_block(const mesh::Mesh& mesh, const material::Material& material) {
  return std::make_unique<ElasticBlock>(mesh, std::vector<material::Material>{material});
}

std::shared_ptr<model::Model> elastic_model(const mesh::Mesh& mesh, std::vector<material::Material> materials,
                                            std::optional<material::Law> law) {
  if (law)
    for (auto& m : materials) m.law = *law;
  auto out = std::make_shared<model::Model>(mesh.dim(), Eigen::Map<const VecX>(mesh.nodes.data(), mesh.nodes.size()));
  out->add(std::make_unique<ElasticBlock>(mesh, materials));
  return out;
}

}  // namespace hooke::fem
