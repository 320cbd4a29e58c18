#include <Eigen/LU>
#include <array>
#include <exception>
#include <hooke/calibrate/cauchy_split.hpp>
#include <hooke/calibrate/detail/element_springs.hpp>
#include <hooke/calibrate/stiffness_fit.hpp>
#include <hooke/core/error.hpp>
#include <hooke/fem/cst.hpp>
#include <hooke/fem/quad4.hpp>
#include <hooke/fem/tet4.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/springs/tet_volume_block.hpp>
#include <limits>

namespace hooke::calibrate {
namespace {

// Hessian at rest of a unit-stiffness spring between local nodes a and b (Lloyd Eq. 6 with k = 1).
MatX unit_spring(const MatX& p, int a, int b) {
  const int d = static_cast<int>(p.cols()), n = static_cast<int>(p.rows());
  const VecX u = (p.row(a) - p.row(b)).transpose().normalized();
  const MatX blk = u * u.transpose();
  MatX h = MatX::Zero(d * n, d * n);
  h.block(d * a, d * a, d, d) = blk;
  h.block(d * b, d * b, d, d) = blk;
  h.block(d * a, d * b, d, d) = -blk;
  h.block(d * b, d * a, d, d) = -blk;
  return h;
}

// Hessian at rest of a unit-k_V volume term on a tet: g g^T / V0^2 (App. C, Eq. 18 at C = 0).
MatX unit_volume(const MatX& p) {
  const Eigen::Matrix<double, 3, 4> corners = p.transpose();
  const Eigen::Matrix<double, 3, 4> grad = springs::tet_volume_gradient(corners);
  const double v0 =
      (corners.col(1) - corners.col(0)).dot((corners.col(2) - corners.col(0)).cross(corners.col(3) - corners.col(0))) /
      6.0;
  const Eigen::Map<const Eigen::Matrix<double, 12, 1>> g(grad.data());
  return g * g.transpose() / (v0 * v0);
}

// Hessian at rest of a spring whose prestress coefficient is a = 1 (tension 1 N/m times its length) and whose
// axial coefficient is zero: the isotropic part a I of k[(1 - l0/l) I + (l0/l) u u^T].
MatX unit_prestress(int d, int n, int a, int b) {
  MatX h = MatX::Zero(d * n, d * n);
  const MatX i = MatX::Identity(d, d);
  h.block(d * a, d * a, d, d) = i;
  h.block(d * b, d * b, d, d) = i;
  h.block(d * a, d * b, d, d) = -i;
  h.block(d * b, d * a, d, d) = -i;
  return h;
}

// Self-stress states of an element's springs: prestress coefficients a_s (tension / length) whose nodal forces
// sum to zero at every node, so that the element rests in its rest shape. One state for a quad with its two
// diagonals (6 bars on 4 nodes in 2D: 6 - (8 - 3) = 1).
MatX self_stress(const MatX& p, const std::vector<std::array<int, 2>>& pairs) {
  const int d = static_cast<int>(p.cols()), n = static_cast<int>(p.rows());
  MatX eq = MatX::Zero(d * n, static_cast<Eigen::Index>(pairs.size()));
  for (size_t s = 0; s < pairs.size(); ++s) {
    const VecX dp = (p.row(pairs[s][0]) - p.row(pairs[s][1])).transpose();
    eq.block(d * pairs[s][0], static_cast<Eigen::Index>(s), d, 1) = dp;
    eq.block(d * pairs[s][1], static_cast<Eigen::Index>(s), d, 1) = -dp;
  }
  Eigen::FullPivLU<MatX> lu(eq);
  lu.setThreshold(1e-10);
  MatX kernel = lu.kernel();
  if (lu.rank() == eq.cols()) return MatX(eq.cols(), 0);
  for (Eigen::Index c = 0; c < kernel.cols(); ++c) kernel.col(c).normalize();
  return kernel;
}

// The material whose tet4 matrix the springs of a tet are fitted to. A spring network's tensor is fully symmetric,
// so the literal fit at nu finds the full symmetrisation lambda' = mu' = (lambda + 2 mu)/3 of the material
// (docs/methods/any_nu.md); the network target is a nu = 1/4 material instead: with E (springs only, Lloyd's
// choice for Eq. 12) or with the shear modulus mu beside an exact volumetric term.
material::Material fit_target(const material::Material& mat, const StiffnessFitOptions& options) {
  if (!options.network_target || options.volume == VolumeTerm::kFitted) return mat;
  material::Material target = mat;
  target.poisson_ratio = 0.25;
  if (options.volume == VolumeTerm::kVolumetric) target.youngs_modulus = cauchy_split(mat).spring_youngs_modulus;
  return target;
}

}  // namespace

VecX fit_nonnegative(const MatX& target, const std::vector<MatX>& bases, double* residual) {
  const int n = static_cast<int>(bases.size());
  if (n > 12) throw InvalidArgument("fit_nonnegative: at most 12 bases");
  MatX g(n, n);
  VecX b(n);
  for (int s = 0; s < n; ++s) {
    b(s) = (target.array() * bases[static_cast<size_t>(s)].array()).sum();
    for (int t = 0; t < n; ++t)
      g(s, t) = (bases[static_cast<size_t>(s)].array() * bases[static_cast<size_t>(t)].array()).sum();
  }
  const double tt = target.squaredNorm();
  VecX best = VecX::Zero(n);
  double best_sq = tt;
  // The unconstrained least-squares solution has the smallest residual of all subsets' solutions: when it is
  // non-negative it is the answer, and the other 2^n - 2 subsets need not be tried (the Stanford bunny's 345 027
  // tets: the same model, calibrate_model 29.9 -> 23.0 s).
  {
    const VecX all = g.completeOrthogonalDecomposition().solve(b);
    const double sq = tt - 2.0 * all.dot(b) + all.dot(g * all);
    if (all.allFinite() && !(all.array() < 0.0).any() && sq < best_sq) {
      if (residual) *residual = std::sqrt(std::max(0.0, sq));
      return all;
    }
  }
  for (int mask = 1; mask < (1 << n); ++mask) {
    std::vector<int> idx;
    for (int s = 0; s < n; ++s)
      if (mask & (1 << s)) idx.push_back(s);
    const int m = static_cast<int>(idx.size());
    MatX gs(m, m);
    VecX bs(m);
    for (int i = 0; i < m; ++i) {
      bs(i) = b(idx[static_cast<size_t>(i)]);
      for (int j = 0; j < m; ++j) gs(i, j) = g(idx[static_cast<size_t>(i)], idx[static_cast<size_t>(j)]);
    }
    const VecX cs = gs.completeOrthogonalDecomposition().solve(bs);
    if ((cs.array() < 0.0).any()) continue;
    const double sq = tt - 2.0 * cs.dot(bs) + cs.dot(gs * cs);
    if (sq < best_sq) {
      best_sq = sq;
      best.setZero();
      for (int i = 0; i < m; ++i) best(idx[static_cast<size_t>(i)]) = cs(i);
    }
  }
  if (residual) *residual = std::sqrt(std::max(0.0, best_sq));
  return best;
}

namespace {

// One element's fit (Sec. 4.2.1): the non-negative coefficients of its bases (springs, then the fitted volume
// term, then +/- each quad self-stress state) that come closest to its FEM stiffness. Reads `acc` only.
struct ElementFit {
  VecX c;       // the coefficients of the element's bases
  MatX states;  // quads: the self-stress states of Eq. 11 (one column each)
};
ElementFit fit_element(const mesh::Mesh& m, const std::vector<material::Material>& materials,
                       const StiffnessFitOptions& options, const detail::EdgeAccumulator& acc, int e) {
  using mesh::ElementKind;
  const int npe = mesh::nodes_per_element(m.kind), d = m.dim();
  const material::Material& mat = materials.size() == 1 ? materials[0] : materials[static_cast<size_t>(e)];
  MatX p(npe, d);
  for (int a = 0; a < npe; ++a) p.row(a) = m.nodes.row(m.elements(e, a));
  MatX k_fem;
  if (m.kind == ElementKind::kTet)
    k_fem = fem::tet4_stiffness(p, fit_target(mat, options));
  else if (m.kind == ElementKind::kQuad)
    k_fem = fem::quad4_stiffness(p, mat);
  else
    k_fem = fem::cst_stiffness(p, mat);
  std::vector<MatX> bases;
  for (const auto& lp : acc.local_pairs()) bases.push_back(unit_spring(p, lp[0], lp[1]));
  if (options.volume == VolumeTerm::kFitted) bases.push_back(unit_volume(p));
  // Quads: the prestrain of Eq. 11 as well. Its isotropic stiffness part a_s I must be a self-stress of the
  // element (else the rest shape is not an equilibrium), a_s = alpha * state_s with alpha of either sign:
  // two non-negative bases, +state and -state.
  ElementFit out;
  if (m.kind == ElementKind::kQuad) out.states = self_stress(p, acc.local_pairs());
  for (Eigen::Index st = 0; st < out.states.cols(); ++st) {
    MatX iso = MatX::Zero(k_fem.rows(), k_fem.cols());
    for (size_t s = 0; s < acc.local_pairs().size(); ++s)
      iso += out.states(static_cast<Eigen::Index>(s), st) *
             unit_prestress(d, npe, acc.local_pairs()[s][0], acc.local_pairs()[s][1]);
    bases.push_back(iso);
    bases.push_back(-iso);
  }
  out.c = fit_nonnegative(k_fem, bases);
  return out;
}

}  // namespace

SpringModel stiffness_fit(const mesh::Mesh& m, const std::vector<material::Material>& materials,
                          const StiffnessFitOptions& options) {
  using mesh::ElementKind;
  if (m.kind == ElementKind::kSurfaceTriangle)
    throw InvalidArgument("stiffness-fit needs a triangle, quad or tet mesh");
  const bool volume_terms = options.volume != VolumeTerm::kNone;
  if (volume_terms && m.kind != ElementKind::kTet) throw InvalidArgument("volume terms need a tet mesh");
  detail::EdgeAccumulator acc(m);
  const int count = m.element_count();
  VecX k_volume = VecX::Zero(volume_terms ? count : 0);
  // The per-element fits are independent: they run on all threads (48 us per tet, most of a scan's calibration),
  // and are added to the springs afterwards in element order, so the sums do not depend on the thread count.
  std::vector<ElementFit> fits(static_cast<size_t>(count));
  std::vector<std::exception_ptr> failed(static_cast<size_t>(count));
#pragma omp parallel for schedule(dynamic, 256)
  for (int e = 0; e < count; ++e) try {
      fits[static_cast<size_t>(e)] = fit_element(m, materials, options, acc, e);
    } catch (...) {
      failed[static_cast<size_t>(e)] = std::current_exception();
    }
  for (const std::exception_ptr& f : failed)
    if (f) std::rethrow_exception(f);  // the first failing element's error, whatever the thread count
  for (int e = 0; e < count; ++e) {
    const material::Material& mat = materials.size() == 1 ? materials[0] : materials[static_cast<size_t>(e)];
    const VecX& c = fits[static_cast<size_t>(e)].c;
    const MatX& states = fits[static_cast<size_t>(e)].states;
    const size_t first_state = acc.local_pairs().size() + (options.volume == VolumeTerm::kFitted ? 1 : 0);
    const std::vector<int> springs = acc.element_springs(e);
    for (size_t s = 0; s < springs.size(); ++s) acc.add(springs[s], c(static_cast<Eigen::Index>(s)));
    if (options.volume == VolumeTerm::kFitted) k_volume(e) = c(static_cast<Eigen::Index>(springs.size()));
    if (options.volume == VolumeTerm::kVolumetric)
      k_volume(e) = cauchy_split(mat).volume_lambda * mesh::element_measure(m, e);  // lambda_V V0 (tr eps)^2 / 2
    for (Eigen::Index st = 0; st < states.cols(); ++st) {
      const double alpha =
          c(static_cast<Eigen::Index>(first_state) + 2 * st) - c(static_cast<Eigen::Index>(first_state) + 2 * st + 1);
      for (size_t s = 0; s < springs.size(); ++s)
        acc.add_prestress(springs[s], alpha * states(static_cast<Eigen::Index>(s), st));
    }
  }
  SpringModel out = acc.finish();
  if (volume_terms && !k_volume.isZero(0.0)) {  // kVolumetric at nu <= 1/4 has none
    out.volume_tets = m.elements;
    out.volume_stiffness = k_volume;
    out.rest_volume.resize(m.element_count());
    for (int e = 0; e < m.element_count(); ++e) out.rest_volume(e) = mesh::element_measure(m, e);
  }
  return out;
}

}  // namespace hooke::calibrate
