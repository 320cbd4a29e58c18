// Arnab & Raja's figures as numbers: Fig. 10 (volume deviation per scheme) and Fig. 8 (displacement patterns
// before and after a local refinement).
#include <cmath>
#include <hooke/calibrate/surface_model.hpp>
#include <hooke/experiments/reproduce_arnab2008.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/problem.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <hooke/surface/refine.hpp>

namespace hooke::experiments {
namespace {

constexpr double kRadius = 0.05;  // m

// Static equilibrium of a surface model under a force `force` (N) along -z at node `node` (the top pole); the
// volume penalty's interaction, where there is one, is centred there with a radius of influence of 2 R.
VecX pushed(const calibrate::SurfaceModel& s, int node, double force) {
  model::Problem p = model::make_problem(s.model);
  p.external_force = VecX::Zero(s.model->dof_count());
  p.external_force(3 * node + 2) = -force;
  if (s.volume) s.volume->set_interaction({s.mesh.nodes.row(node).transpose(), Vec3(0, 0, -1), 2.0 * kRadius});
  solve::NewtonOptions newton;
  newton.max_iterations = 100;
  const solve::StaticResult r = solve::static_equilibrium(p, newton);
  solve::require_converged(r.report);
  return r.positions;
}

mesh::Mesh sphere() { return mesh::uv_sphere_surface(12, 20, kRadius); }  // 222 nodes, irregular near the poles

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
          100.0 * std::abs(surface::enclosed_volume(s.mesh.elements, x) / s.discretisation.volume - 1.0));
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

}  // namespace hooke::experiments
