// Arnab & Raja's figures as numbers: Fig. 10 (volume deviation per scheme) and Fig. 8 (displacement patterns
// before and after a local refinement).
#include <cmath>
#include <cstdio>
#include <hooke/calibrate/surface_model.hpp>
#include <hooke/experiments/detail/face_load.hpp>
#include <hooke/experiments/reproduce_arnab2008.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/problem.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <hooke/surface/refine.hpp>
#include <map>

namespace hooke::experiments {
namespace {

constexpr double kRadius = 0.05;  // m

// Static equilibrium of a surface model under a force `force` (N) along -z at node `node` (the top pole); the
// volume penalty's interaction, where there is one, is centred there with a radius of influence of 2 R.
VecX pushed(const calibrate::SurfaceModel& s, int node, double force) {
  model::Problem p = model::make_problem(s.model);
  p.external_force = VecX::Zero(s.model->dof_count());
  p.external_force(3 * node + 2) = -force;
  if (s.volume) p.interaction = model::Interaction{s.mesh.nodes.row(node).transpose(), Vec3(0, 0, -1), 2.0 * kRadius};
  solve::StaticOptions statics;
  statics.newton.max_iterations = 100;
  const solve::StaticResult r = solve::static_equilibrium(p, statics);
  solve::require_converged(r.report);
  return r.positions;
}

mesh::Mesh sphere() { return mesh::uv_sphere_surface(12, 20, kRadius); }  // 222 nodes, irregular near the poles

// Side view (x across, z up) of a surface at rest (grey) and deformed (red), displacements times `magnify`.
DeformationPanel shape_panel(const std::string& title, const mesh::Mesh& m, const VecX& rest, const VecX& deformed,
                             double magnify) {
  DeformationPanel p;
  p.title = title;
  p.axes = {0, 2};
  const VecX shown = rest + magnify * (deformed - rest);
  p.drawings.push_back({"rest", "lightgrey", 0.3, drawing_edges(m), m.nodes});
  p.drawings.push_back({"deformed", "red", 0.4, drawing_edges(m), mesh::positions_as_rows(shown, 3)});
  return p;
}

}  // namespace

std::vector<VolumeDeviationRow> arnab2008_fig10(double nu) {
  const std::vector<double> forces{0.002, 0.004, 0.006, 0.008, 0.010};
  std::vector<VolumeDeviationRow> rows;
  for (calibrate::SurfaceScheme scheme : {calibrate::SurfaceScheme::kA, calibrate::SurfaceScheme::kB,
                                          calibrate::SurfaceScheme::kC, calibrate::SurfaceScheme::kD}) {
    calibrate::SurfaceOptions o;
    o.scheme = scheme;
    const calibrate::SurfaceModel s = calibrate::make_surface_model(sphere(), {material::Law::kLinear, 100.0, nu}, o);
    VolumeDeviationRow row;
    row.scheme = std::string(calibrate::surface_scheme_name(scheme));
    for (double f : forces) {
      const VecX x = pushed(s, 0, f);
      row.force.push_back(f);
      row.deviation_percent.push_back(
          100.0 * std::abs(mesh::enclosed_volume(s.mesh.elements, x) / s.discretisation.volume - 1.0));
    }
    for (double d : row.deviation_percent) row.average_percent += d / static_cast<double>(forces.size());
    rows.push_back(row);
  }
  return rows;
}

std::vector<RefinementRow> arnab2008_fig8(double nu, int& sphere_nodes, int& refined_nodes) {
  const mesh::Mesh coarse = sphere();
  const Vec3 top = coarse.nodes.row(0).transpose();
  const mesh::Mesh fine = surface::refine_near(coarse, top, 0.02);
  sphere_nodes = coarse.node_count();
  refined_nodes = fine.node_count();
  std::vector<RefinementRow> rows;
  for (calibrate::SurfaceScheme scheme : {calibrate::SurfaceScheme::kC, calibrate::SurfaceScheme::kD}) {
    calibrate::SurfaceOptions o;
    o.scheme = scheme;
    const material::Material mat{material::Law::kLinear, 10.0, nu};
    const calibrate::SurfaceModel sc = calibrate::make_surface_model(coarse, mat, o);
    const calibrate::SurfaceModel sf = calibrate::make_surface_model(fine, mat, o);
    for (double f : {0.0002, 0.0004, 0.0006, 0.0008, 0.0010}) {
      const VecX xc = pushed(sc, 0, f), xf = pushed(sf, 0, f);
      // Original nodes keep their indices in the refined mesh.
      std::vector<double> diff;
      for (int i = 0; i < coarse.node_count(); ++i)
        if ((coarse.nodes.row(i).transpose() - top).norm() <= 0.02) {
          const double uc = (xc.segment<3>(3 * i) - sc.model->rest_positions().segment<3>(3 * i)).norm();
          const double uf = (xf.segment<3>(3 * i) - sf.model->rest_positions().segment<3>(3 * i)).norm();
          diff.push_back(uf - uc);
        }
      RefinementRow row;
      row.scheme = std::string(calibrate::surface_scheme_name(scheme));
      row.force = f;
      row.compared_nodes = static_cast<int>(diff.size());
      double mean = 0.0, mean_abs = 0.0;
      for (double d : diff) {
        mean += d / static_cast<double>(diff.size());
        mean_abs += std::abs(d) / static_cast<double>(diff.size());
      }
      double var = 0.0;
      for (double d : diff) var += (d - mean) * (d - mean) / static_cast<double>(diff.size());
      row.standard_deviation_mm = 1e3 * std::sqrt(var);
      row.mean_deviation_mm = 1e3 * mean_abs;
      row.peak_displacement_mm = 1e3 * (xc.segment<3>(0) - sc.model->rest_positions().segment<3>(0)).norm();
      rows.push_back(row);
    }
  }
  return rows;
}

ShearComparison arnab2008_fig12(double nu, Figure* figure) {
  const int n = 10;
  const double a = 0.1, e = 3250.0;
  ShearComparison out;
  out.youngs_modulus = e;
  out.shear_stress = 0.05 * e;
  const calibrate::SurfaceModel s =
      calibrate::make_surface_model(mesh::cube_surface(n, a), {material::Law::kLinear, e, nu});
  const mesh::Mesh tets = mesh::tet_box(a, a, a, n, n, n);
  out.surface_nodes = s.mesh.node_count();
  out.fem_nodes = tets.node_count();
  // Surface node -> the tet node at the same place (both meshes use the same n^3 grid).
  auto grid_key = [&](const Eigen::Ref<const RowMatX>& nodes, int i) {
    std::array<long, 3> k{};
    for (int d = 0; d < 3; ++d) k[static_cast<size_t>(d)] = std::lround(nodes(i, d) / a * n);
    return k;
  };
  std::map<std::array<long, 3>, int> tet_node;
  for (int i = 0; i < tets.node_count(); ++i) tet_node[grid_key(tets.nodes, i)] = i;
  std::vector<int> twin(static_cast<size_t>(s.mesh.node_count()));
  for (int i = 0; i < s.mesh.node_count(); ++i) twin[static_cast<size_t>(i)] = tet_node.at(grid_key(s.mesh.nodes, i));
  // Shear load: sigma A_t / 3 along x per node of each top triangle; the same nodal forces on both models.
  model::Problem ps = model::make_problem(s.model);
  ps.external_force = detail::top_face_load(s.mesh, a, Vec3(out.shear_stress, 0, 0));
  std::vector<int> bottom_surface, bottom_tets;
  for (int i = 0; i < s.mesh.node_count(); ++i)
    if (s.mesh.nodes(i, 2) < 1e-12 * a) bottom_surface.push_back(i);
  for (int i = 0; i < tets.node_count(); ++i)
    if (tets.nodes(i, 2) < 1e-12 * a) bottom_tets.push_back(i);
  model::fix_nodes(ps, bottom_surface);
  auto fem_model = fem::linear_model(tets, {{material::Law::kLinear, e, nu}});
  model::Problem pf = model::make_problem(fem_model);
  pf.external_force = VecX::Zero(fem_model->dof_count());
  for (int i = 0; i < s.mesh.node_count(); ++i)
    pf.external_force.segment<3>(3 * twin[static_cast<size_t>(i)]) = ps.external_force.segment<3>(3 * i);
  model::fix_nodes(pf, bottom_tets);
  const solve::StaticResult rf = solve::linear_static(pf);
  solve::require_converged(rf.report);
  solve::StaticOptions statics;
  statics.newton.max_iterations = 100;
  const solve::StaticResult rs = solve::static_equilibrium(ps, statics);
  solve::require_converged(rs.report);
  double top_sum = 0.0;
  int top_count = 0;
  for (int i = 0; i < s.mesh.node_count(); ++i) {
    const int j = twin[static_cast<size_t>(i)];
    const Vec3 us = rs.positions.segment<3>(3 * i) - s.model->rest_positions().segment<3>(3 * i);
    const Vec3 uf = rf.positions.segment<3>(3 * j) - fem_model->rest_positions().segment<3>(3 * j);
    const double err = 1e3 * (us - uf).norm();
    out.fem_max_mm = std::max(out.fem_max_mm, 1e3 * uf.norm());
    out.surface_max_mm = std::max(out.surface_max_mm, 1e3 * us.norm());
    out.max_error_mm = std::max(out.max_error_mm, err);
    out.mean_error_mm += err / s.mesh.node_count();
    if (s.mesh.nodes(i, 2) > a * (1.0 - 1e-12)) {
      top_sum += err;
      ++top_count;
    }
  }
  out.top_mean_error_mm = top_sum / top_count;
  if (figure) {
    char title[160];
    std::snprintf(title, sizeof title, "%.4g Pa: FEM max %.1f mm, ours %.1f mm", out.shear_stress, out.fem_max_mm,
                  out.surface_max_mm);
    DeformationPanel panel = deformation_panel(title, tets, rf.positions, s.mesh, rs.positions);
    panel.axes = {0, 2};
    *figure = {"fig12_shear", "Fig. 12: sheared cube, FEM black, surface model red", {panel}};
  }
  return out;
}

std::vector<GravityRow> arnab2008_fig9(double nu, Figure* figure) {
  std::vector<GravityRow> rows;
  std::vector<std::variant<DeformationPanel, CurvePanel>> panels;
  for (calibrate::SurfaceScheme scheme : {calibrate::SurfaceScheme::kB, calibrate::SurfaceScheme::kD}) {
    calibrate::SurfaceOptions o;
    o.scheme = scheme;
    const calibrate::SurfaceModel s = calibrate::make_surface_model(sphere(), {material::Law::kLinear, 10000.0, nu}, o);
    model::Problem p = model::make_problem(s.model);
    p.external_force = VecX::Zero(s.model->dof_count());
    for (int i = 0; i < s.mesh.node_count(); ++i) p.external_force(3 * i + 2) = -9.81 * s.masses(3 * i);
    solve::StaticOptions statics;
    statics.newton.max_iterations = 100;
    const solve::StaticResult r = solve::static_equilibrium(p, statics);
    solve::require_converged(r.report);
    const int n = s.mesh.node_count();
    VecX sag(n);
    for (int i = 0; i < n; ++i) sag(i) = s.model->rest_positions()(3 * i + 2) - r.positions(3 * i + 2);
    GravityRow row;
    row.scheme = std::string(calibrate::surface_scheme_name(scheme));
    row.mean_sag_mm = 1e3 * sag.mean();
    row.sag_spread_percent = 100.0 * std::sqrt((sag.array() - sag.mean()).square().mean()) / sag.mean();
    row.volume_deviation_percent =
        100.0 * std::abs(mesh::enclosed_volume(s.mesh.elements, r.positions) / s.discretisation.volume - 1.0);
    rows.push_back(row);
    if (figure)
      panels.push_back(shape_panel("scheme " + row.scheme + " (displacements x 20)", s.mesh, s.model->rest_positions(),
                                   r.positions, 20.0));
  }
  if (figure) *figure = {"fig09_gravity", "Fig. 9: gravity on the sphere, schemes B and D", panels};
  return rows;
}

std::vector<WeightsRow> arnab2008_fig11(double nu, Figure* figure) {
  std::vector<WeightsRow> rows;
  std::vector<std::variant<DeformationPanel, CurvePanel>> panels;
  for (const bool run_time : {false, true}) {
    const calibrate::SurfaceModel s = calibrate::make_surface_model(sphere(), {material::Law::kLinear, 100.0, nu});
    model::Problem p = model::make_problem(s.model);
    p.external_force = VecX::Zero(s.model->dof_count());
    p.external_force(2) = -0.005;  // node 0: the top pole
    if (run_time) p.interaction = model::Interaction{s.mesh.nodes.row(0).transpose(), Vec3(0, 0, -1), 2.0 * kRadius};
    solve::StaticOptions statics;
    statics.newton.max_iterations = 100;
    const solve::StaticResult r = solve::static_equilibrium(p, statics);
    solve::require_converged(r.report);
    const VecX u = r.positions - s.model->rest_positions();
    WeightsRow row;
    row.weights = run_time ? "run-time" : "uniform";
    row.pushed_node_mm = -1e3 * u(2);
    row.opposite_pole_mm = -1e3 * u(3 * (s.mesh.node_count() - 1) + 2);
    int equator = 0;
    for (int i = 0; i < s.mesh.node_count(); ++i)
      if (std::abs(s.mesh.nodes(i, 2)) < 1e-9 * kRadius) {
        row.equator_outward_mm += 1e3 * u.segment<3>(3 * i).dot(s.mesh.nodes.row(i).transpose().normalized());
        ++equator;
      }
    row.equator_outward_mm /= std::max(equator, 1);
    row.volume_deviation_percent =
        100.0 * std::abs(mesh::enclosed_volume(s.mesh.elements, r.positions) / s.discretisation.volume - 1.0);
    rows.push_back(row);
    if (figure)
      panels.push_back(shape_panel(row.weights + " weights", s.mesh, s.model->rest_positions(), r.positions, 1.0));
  }
  if (figure) *figure = {"fig11_weights", "Fig. 11: a push on the top node, uniform and run-time weights", panels};
  return rows;
}

std::vector<Figure> arnab2008_curve_figures(const Arnab2008Report& r) {
  CurvePanel deviation{"volume deviation under a point force", "force (mN)", "|V - V0| / V0 (%)", {}};
  const char* styles[4] = {"s-", "^-", "o-", "D-"};
  for (size_t k = 0; k < r.fig10.size(); ++k) {
    Series series{"scheme " + r.fig10[k].scheme, styles[k % 4], {}, r.fig10[k].deviation_percent};
    for (double f : r.fig10[k].force) series.x.push_back(1e3 * f);
    deviation.series.push_back(series);
  }
  CurvePanel spread{"(a) standard deviation of the patterns", "force (mN)", "std (mm)", {}};
  CurvePanel mean{"(b) mean displacement deviation", "force (mN)", "mean (mm)", {}};
  for (const char* scheme : {"C", "D"}) {
    Series a{std::string("scheme ") + scheme, scheme[0] == 'C' ? "o-" : "D-", {}, {}}, b = a;
    for (const auto& row : r.fig8)
      if (row.scheme == scheme) {
        a.x.push_back(1e3 * row.force);
        a.y.push_back(row.standard_deviation_mm);
        b.x.push_back(1e3 * row.force);
        b.y.push_back(row.mean_deviation_mm);
      }
    spread.series.push_back(a);
    mean.series.push_back(b);
  }
  return {{"fig08_refinement",
           "Arnab & Raja Fig. 8: displacement patterns before and after a local refinement",
           {spread, mean}},
          {"fig10_volume_deviation", "Arnab & Raja Fig. 10: volume deviation per scheme", {deviation}}};
}

}  // namespace hooke::experiments
