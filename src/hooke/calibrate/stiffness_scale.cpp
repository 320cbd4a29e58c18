#include <Eigen/SVD>
#include <cmath>
#include <hooke/calibrate/stiffness_scale.hpp>
#include <hooke/core/sparse_cholesky.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/model/free_map.hpp>
#include <hooke/model/mass.hpp>
#include <hooke/model/problem.hpp>
#include <hooke/model/support.hpp>
#include <memory>

namespace hooke::calibrate {
namespace {

// True when holding `nodes` removes every rigid motion: two distinct nodes in 2D, three not on a line in 3D. (A
// factorisation does not detect the singular alternative reliably: roundoff leaves tiny positive pivots.)
bool holds_rigidly(const mesh::Mesh& m, const std::vector<int>& nodes) {
  if (nodes.size() < static_cast<size_t>(m.dim())) return false;
  RowMatX p(static_cast<Eigen::Index>(nodes.size()), m.dim());
  for (size_t i = 0; i < nodes.size(); ++i) p.row(static_cast<Eigen::Index>(i)) = m.nodes.row(nodes[i]);
  p.rowwise() -= p.colwise().mean();
  const VecX sv = Eigen::JacobiSVD<MatX>(MatX(p)).singularValues();
  const double scale = mesh::bounding_box_diagonal(m);
  return sv(m.dim() - 2) > 1e-6 * scale;
}

// Sum over load cases (columns) of w_a a_a . b_a.
double weighted_dot(const MatX& a, const MatX& b, const VecX& w) {
  return (a.array() * b.array()).colwise().sum().matrix().dot(w);
}

// Displacements (free DOFs x 3 load cases) of the matrix factorised in `c`.
MatX solve_all(const SparseCholesky& c, const MatX& loads) {
  MatX u(loads.rows(), loads.cols());
  for (Eigen::Index j = 0; j < loads.cols(); ++j) u.col(j) = c.solve(loads.col(j));
  return u;
}

// The self-weight problem on one support, on its free DOFs: the springs' and volume terms' stiffness, the unit
// body loads, the FEM's displacements under them and each load's weight; `chol` factorises K(c) = c K_s + K_V.
struct HeldProblem {
  const SparseMatrix& ks;
  const SparseMatrix& kv;
  const MatX& loads;
  const MatX& u_fem;
  const VecX& w;
  SparseCholesky& chol;

  // G: sum over loads of w_a |u_a - u_FEM,a|^2.
  double relative_g(const MatX& u_c) const { return weighted_dot(u_c - u_fem, u_c - u_fem, w); }
  int factorizations = 0;  // of K(c), by displacements()

  // u(c) into u, leaving K(c) factorised; false when K(c) is not positive definite.
  bool displacements(double c, MatX& u) {
    ++factorizations;
    if (!chol.factorize(SparseMatrix(c * ks + kv))) return false;
    u = solve_all(chol, loads);
    return true;
  }
};

// G restricted to a subspace: u_a(c) ~ V y_a(c), y(c) = (c V^T K_s V + V^T K_V V)^-1 V^T F (Galerkin), V orthonormal,
// so that |V y_a - u_FEM,a|^2 = |y_a|^2 - 2 y_a . V^T u_FEM,a + |u_FEM,a|^2 exactly.
struct ReducedSelfWeight {
  MatX as, av, b, vu;  // V^T K_s V, V^T K_V V (r x r), V^T F, V^T u_FEM (r x loads)
  VecX fem_sq, w;      // |u_FEM,a|^2, the loads' weights

  MatX y(double c) const { return MatX(c * as + av).ldlt().solve(b); }
  double g(const MatX& ya) const {
    VecX out(ya.cols());
    for (Eigen::Index a = 0; a < ya.cols(); ++a)
      out(a) = ya.col(a).squaredNorm() - 2.0 * ya.col(a).dot(vu.col(a)) + fem_sq(a);
    return out.dot(w);
  }
  // Gauss-Newton on the reduced G from c = 1 (the steps of gauss_newton_scale, to 1e-12 of c); 0 when it fails.
  double minimiser() const {
    double c = 1.0;
    MatX ya = y(c);
    double gc = g(ya);
    for (int it = 0; it < 100; ++it) {
      const MatX dy = -MatX(c * as + av).ldlt().solve(MatX(as * ya));  // dy/dc
      const double jj = (dy.array().square().colwise().sum().matrix() * w)(0);
      const double jr = ((dy.array() * (ya - vu).array()).colwise().sum().matrix() * w)(0);
      if (!(jj > 0.0)) return 0.0;
      double step = -jr / jj;
      if (std::abs(step) <= 1e-12 * c) return c;
      for (; std::abs(step) > 1e-14 * c; step *= 0.5) {
        if (c + step <= 0.0) continue;
        const MatX yt = y(c + step);
        const double gt = g(yt);
        if (std::isfinite(gt) && gt <= gc) {
          c += step, ya = yt, gc = gt;
          break;
        }
      }
      if (std::abs(step) <= 1e-14 * c) return c;
    }
    return c;
  }
};

// Appends to the orthonormal columns of v those of `block` that are new (modified Gram-Schmidt, twice), and returns
// how many were added. A column whose new part is below 1e-10 of its norm is dropped.
Eigen::Index orthonormal_append(MatX& v, MatX block) {
  Eigen::Index added = 0;
  for (Eigen::Index j = 0; j < block.cols(); ++j) {
    VecX x = block.col(j);
    const double norm = x.norm();
    for (int pass = 0; pass < 2; ++pass)
      for (Eigen::Index k = 0; k < v.cols(); ++k) x -= v.col(k).dot(x) * v.col(k);
    if (!(x.norm() > 1e-10 * norm)) continue;
    v.conservativeResize(x.size(), v.cols() + 1);
    v.col(v.cols() - 1) = x / x.norm();
    ++added;
  }
  return added;
}

// A start for gauss_newton_scale that needs no factorisation: the minimiser of G on the block Krylov space
// span{u(1), S u(1), S^2 u(1), ...}, S = K(1)^-1 K_s, built with the factor of K(1) that p holds (solves only).
// The space holds the Taylor terms of u(c) = sum_k (1 - c)^k S^k u(1) about c = 1, so the reduced minimiser
// converges to the true one as blocks are added (in 3-6 blocks on the scans, to 1e-9 of c); blocks are added until
// it moves by less than 1e-9 of itself, at most 12. Returns 0 where the reduced problem has no minimiser.
// @pre p.chol holds K(1), u = u(1)
double reduced_minimiser(const HeldProblem& p, const MatX& u) {
  ReducedSelfWeight r;
  r.w = p.w;
  r.fem_sq = p.u_fem.colwise().squaredNorm().transpose();
  MatX v(u.rows(), 0), ksv(u.rows(), 0), kvv(u.rows(), 0);  // V, K_s V and K_V V, grown a block at a time
  MatX block = u;
  double c = 0.0;
  for (int k = 0; k < 12; ++k) {
    const Eigen::Index first = v.cols();
    if (orthonormal_append(v, block) == 0) break;
    const Eigen::Index added = v.cols() - first;
    ksv.conservativeResize(Eigen::NoChange, v.cols());
    kvv.conservativeResize(Eigen::NoChange, v.cols());
    ksv.rightCols(added) = p.ks * v.rightCols(added);
    kvv.rightCols(added) = p.kv * v.rightCols(added);
    r.as = v.transpose() * ksv;
    r.av = v.transpose() * kvv;
    r.b = v.transpose() * p.loads;
    r.vu = v.transpose() * p.u_fem;
    const double next = r.minimiser();
    if (k > 0 && next > 0.0 && std::abs(next - c) <= 1e-9 * next) return next;
    c = next;
    block = solve_all(p.chol, MatX(ksv.rightCols(added)));
  }
  return c;
}

// Gauss-Newton on G(c) from the reduced minimiser (or c = 1), du/dc = -K(c)^-1 K_s u(c), with step halving.
// @pre u = u(1) with K(1) factorised. Returns c; u is then u(c); `steps` counts the Gauss-Newton steps.
double gauss_newton_scale(HeldProblem& p, MatX& u, int& steps) {
  double c = 1.0;
  double g = p.relative_g(u);
  // From the reduced model's minimiser where it is no worse than c = 1: then the loop below normally only confirms
  // it (its first step is below 1e-6 of c), two factorisations of K(c) in all instead of one per step.
  if (const double start = reduced_minimiser(p, u); start > 0.0 && std::abs(start - c) > 1e-6 * c) {
    MatX trial;
    if (p.displacements(start, trial) && p.relative_g(trial) <= g) {
      c = start;
      g = p.relative_g(trial);
      u = std::move(trial);
    } else if (!p.displacements(c, u)) {
      return c;  // K(1) was positive definite a moment ago: not reached
    }
  }
  for (int it = 0; it < 50; ++it) {
    const MatX j = -solve_all(p.chol, MatX(p.ks * u));
    const double jj = weighted_dot(j, j, p.w);
    if (!(jj > 0.0)) break;
    const double full = -weighted_dot(j, u - p.u_fem, p.w) / jj;
    // A step that would change c below its 7th digit is not taken: it would move every spring by less than
    // 1e-6 of itself, against the fit's own error of a few % (the femur's last step was 6e-12 of c), and
    // evaluating it costs a factorisation (9 s on a scan's 233 000 DOFs).
    if (std::abs(full) <= 1e-6 * c) break;
    double accepted_step = 0.0;
    MatX trial;
    for (double step = full; accepted_step == 0.0 && std::abs(step) > 1e-14 * c; step *= 0.5)
      if (c + step > 0.0 && p.displacements(c + step, trial) && p.relative_g(trial) <= g) {
        accepted_step = step;  // chol now holds K(c + step), the next Jacobian's matrix
        c += step;
        g = p.relative_g(trial);
        u = trial;
      }
    ++steps;
    if (accepted_step == 0.0 || std::abs(accepted_step) <= 1e-10 * c) break;
  }
  return c;
}

}  // namespace

SpringModel with_scaled_springs(SpringModel springs, double factor) {
  springs.stiffness *= factor;
  return springs;
}

StiffnessScale fit_self_weight_scale(const mesh::Mesh& mesh, const std::vector<material::Material>& materials,
                                     const SpringModel& springs) {
  StiffnessScale out;
  const int d = mesh.dim(), n = mesh.node_count();
  const VecX rest = Eigen::Map<const VecX>(mesh.nodes.data(), mesh.nodes.size());  // row-major: node-major flat

  // K_FEM of the linear law (every law linearises to it at rest), the springs' K_s and the volume terms' K_V.
  const auto fem_model = fem::linear_model(mesh, materials);
  const SparseMatrix k_fem = fem_model->hessian(rest);
  const SparseMatrix k_springs = linearised_stiffness(mesh, springs_part(springs));
  const bool has_volume = springs.volume_stiffness.size() > 0;
  const SparseMatrix k_volume =
      has_volume ? linearised_stiffness(mesh, volume_part(springs)) : SparseMatrix(k_fem.rows(), k_fem.cols());

  // Unit body force along each axis: nodal forces = the lumped volume (area x t in 2D) of each node.
  const VecX weight = model::lumped_masses(mesh, 1.0, materials.front().thickness);

  for (double slab : {model::kFace, 0.05, 0.10, 0.20}) {  // the bottom face, then ever wider slabs
    const std::vector<int> held = model::end_nodes(mesh, mesh.dim() - 1, model::End::kLow, slab);
    if (!holds_rigidly(mesh, held)) continue;
    model::Problem held_body = model::make_problem(fem_model);
    model::fix_nodes(held_body, held);
    const model::FreeMap map(model::free_dofs(held_body), d * n);
    const std::vector<int>& free_dofs = map.free;
    if (free_dofs.empty()) break;
    MatX loads = MatX::Zero(static_cast<Eigen::Index>(free_dofs.size()), d);
    for (size_t r = 0; r < free_dofs.size(); ++r)
      loads(static_cast<Eigen::Index>(r), free_dofs[r] % d) = weight(free_dofs[r]);

    SparseCholesky chol;
    ++out.factorizations;
    if (!chol.factorize(map.restrict(k_fem))) continue;  // not held: widen the support
    const MatX u_fem = solve_all(chol, loads);
    const SparseMatrix ks = map.restrict(k_springs), kv = map.restrict(k_volume);
    // Each load counts by its relative error (w_a = 1 / |u_FEM,a|^2), the measure of `hooke compare`: unweighted,
    // the sideways loads, which bend a slender body far more than the axial one compresses it, would decide c alone.
    const VecX w = u_fem.colwise().squaredNorm().cwiseInverse().transpose();
    HeldProblem held_problem{ks, kv, loads, u_fem, w, chol};
    MatX u;
    const bool held_definite = held_problem.displacements(1.0, u);
    out.factorizations += held_problem.factorizations;
    held_problem.factorizations = 0;
    if (!held_definite) {
      out.note = "the fitted springs' stiffness held at the bottom is not positive definite";
      continue;
    }
    out.note.clear();
    out.held_nodes = static_cast<int>(held.size());
    out.error_before = std::sqrt(held_problem.relative_g(u) / static_cast<double>(d));
    double c = 1.0;
    if (!has_volume) {
      // u(c) = u(1) / c: the minimiser of sum_a w_a |u_a(1)/c - u_FEM,a|^2 over 1/c.
      const double cross = weighted_dot(u, u_fem, w);
      if (!(cross > 0.0)) {
        out.note = "the springs move against the FEM under self-weight";
        return out;
      }
      c = weighted_dot(u, u, w) / cross;
    } else {
      c = gauss_newton_scale(held_problem, u, out.gauss_newton);
    }
    out.factor = c;
    out.factorizations += held_problem.factorizations;
    out.error_after = std::sqrt(held_problem.relative_g(has_volume ? u : MatX(u / c)) / static_cast<double>(d));
    return out;
  }
  if (out.note.empty()) out.note = "no support up to 20 % of the height holds the body";
  return out;
}

}  // namespace hooke::calibrate
