// Uniaxial bar: (1) uniform tension with symmetry supports gives u = sigma L / E and lateral contraction
// nu eps exactly; (2) a bar under a uniform axial body force (stress varying linearly along it) converges
// to the analytic solution at second order in h. The measured errors are printed for the record.
#include <gtest/gtest.h>

#include <cmath>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <iostream>
#include <support/meshes.hpp>

namespace hooke::fem {
namespace {

constexpr double kE = 14630.0, kNu = 0.3, kT = 0.001;

model::Problem bar_problem(const mesh::Mesh& m) {
  auto model = std::make_shared<model::Model>(m.dim(), test::flat_positions(m));
  model->add(make_elastic_block(m, {material::Law::kLinear, kE, kNu, material::Plane::kStress, kT}));
  return model::make_problem(model);
}

void uniform_tension(const mesh::Mesh& m, double width, double length) {
  const int d = m.dim(), up = d - 1;
  const double sigma = 500.0;
  model::Problem p = bar_problem(m);
  const auto lc = model::make_load_case(m, model::LoadKind::kStretch, sigma, kT);
  p.external_force = lc.nodal_forces;
  // Symmetry supports: bottom slides freely in-plane; one corner pinned; in 3D one more node stops the spin.
  for (int i : lc.fixed_nodes) p.fixed_dofs[static_cast<size_t>(d * i + up)] = 1;
  for (int i = 0; i < m.node_count(); ++i) {
    const bool origin = m.nodes.row(i).norm() < 1e-12;
    const bool x_corner =
        d == 3 && std::abs(m.nodes(i, 0) - width) < 1e-12 && std::abs(m.nodes(i, 1)) + std::abs(m.nodes(i, 2)) < 1e-12;
    if (origin)
      for (int c = 0; c < d; ++c) p.fixed_dofs[static_cast<size_t>(d * i + c)] = 1;
    if (x_corner) p.fixed_dofs[static_cast<size_t>(d * i + 1)] = 1;
  }
  const auto r = solve::linear_static(p);
  solve::require_converged(r.report);
  const VecX u = r.positions - p.model->rest_positions();
  const double eps = sigma / kE;
  double worst_axial = 0, worst_lateral = 0;
  for (int i = 0; i < m.node_count(); ++i) {
    worst_axial = std::max(worst_axial, std::abs(u(d * i + up) - eps * m.nodes(i, up)));
    for (int c = 0; c < up; ++c)
      worst_lateral = std::max(worst_lateral, std::abs(u(d * i + c) + kNu * eps * m.nodes(i, c)));
  }
  std::cout << "[bar] " << mesh::element_kind_name(m.kind) << " uniform tension: tip u = " << eps * length
            << " m expected, max axial error " << worst_axial << " m, max lateral error " << worst_lateral << " m\n";
  EXPECT_LT(worst_axial, 1e-10 * eps * length);
  EXPECT_LT(worst_lateral, 1e-10 * eps * length);
}

TEST(BarUniformTension, ExactForTrianglesQuadsAndTets) {
  uniform_tension(test::perturb_interior(mesh::rectangle_triangles(0.01, 0.04, 3, 12), 0.2), 0.01, 0.04);
  uniform_tension(test::perturb_interior(mesh::rectangle_quads(0.01, 0.04, 3, 12), 0.2), 0.01, 0.04);
  uniform_tension(test::perturb_interior(mesh::tet_box(0.01, 0.01, 0.04, 2, 2, 8), 0.2), 0.01, 0.04);
}

// Exact solution of a bar [0,W]^(d-1) x [0,L] under the axial body force b (N/m^3): sigma_axial = b (L - s).
VecX exact_body_force_displacement(const mesh::Mesh& m, double b, double length) {
  const int d = m.dim(), up = d - 1;
  VecX u(d * m.node_count());
  for (int i = 0; i < m.node_count(); ++i) {
    const double s = m.nodes(i, up);
    double r2 = 0;
    for (int c = 0; c < up; ++c) {
      u(d * i + c) = -kNu * b * (length - s) * m.nodes(i, c) / kE;
      r2 += m.nodes(i, c) * m.nodes(i, c);
    }
    u(d * i + up) = b / kE * (length * s - 0.5 * s * s) - kNu * b * r2 / (2 * kE);
  }
  return u;
}

double body_force_error(const mesh::Mesh& m, double length) {
  const int d = m.dim(), up = d - 1, npe = mesh::nodes_per_element(m.kind);
  const double b = 2.0e5;  // N/m^3
  model::Problem p = bar_problem(m);
  for (int e = 0; e < m.element_count(); ++e) {
    const double measure = mesh::element_measure(m, e) * (d == 2 ? kT : 1.0);
    for (int a = 0; a < npe; ++a) p.external_force(d * m.elements(e, a) + up) += b * measure / npe;
  }
  const VecX exact = exact_body_force_displacement(m, b, length);
  p.prescribed_positions = p.model->rest_positions() + exact;
  for (int i = 0; i < m.node_count(); ++i)
    if (m.nodes(i, up) < 1e-12)
      for (int c = 0; c < d; ++c) {
        p.fixed_dofs[static_cast<size_t>(d * i + c)] = 1;
        p.external_force(d * i + c) = 0.0;
      }
  const auto r = solve::linear_static(p);
  solve::require_converged(r.report);
  // Root-mean-square nodal error relative to the largest displacement (the max norm carries a log h factor).
  const VecX err = (r.positions - p.model->rest_positions()) - exact;
  return std::sqrt(err.squaredNorm() / static_cast<double>(err.size())) / exact.cwiseAbs().maxCoeff();
}

TEST(BarBodyForce, ConvergesAtSecondOrder) {
  std::vector<double> tri, tet;
  for (int n : {1, 2, 4, 8}) {
    tri.push_back(body_force_error(mesh::rectangle_triangles(0.01, 0.04, 2 * n, 8 * n), 0.04));
    tet.push_back(body_force_error(mesh::tet_box(0.01, 0.01, 0.04, n, n, 4 * n), 0.04));
  }
  for (size_t k = 0; k + 1 < tri.size(); ++k) {
    const double rate = std::log2(tri[k] / tri[k + 1]);
    std::cout << "[bar] triangles h/" << (1 << k) << ": relative RMS error " << tri[k] << ", rate " << rate << "\n";
    EXPECT_GT(rate, 1.8);
  }
  // The six-tet cube split is pre-asymptotic on the coarsest meshes: the rate climbs towards 2.
  double previous_rate = 0.0;
  for (size_t k = 0; k + 1 < tet.size(); ++k) {
    const double rate = std::log2(tet[k] / tet[k + 1]);
    std::cout << "[bar] tets h/" << (1 << k) << ": relative RMS error " << tet[k] << ", rate " << rate << "\n";
    EXPECT_GT(rate, previous_rate);
    previous_rate = rate;
  }
  EXPECT_GT(previous_rate, 1.6);
  EXPECT_LT(tri.back(), 0.01);
}

}  // namespace
}  // namespace hooke::fem
