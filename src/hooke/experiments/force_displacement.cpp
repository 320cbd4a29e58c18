#include <cmath>
#include <hooke/experiments/force_displacement.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/model/support.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <limits>

namespace hooke::experiments {
namespace {

struct Ends {
  std::vector<int> bottom, top;
};

// The bottom and top faces (model/support.hpp) along y.
Ends ends(const mesh::Mesh& m) {
  return {model::end_nodes(m, 1, model::End::kLow, model::kFace),
          model::end_nodes(m, 1, model::End::kHigh, model::kFace)};
}

double mean_top_y(const mesh::Mesh& m, const Ends& e, const VecX& x) {
  double s = 0.0;
  for (int i : e.top) s += x(m.dim() * i + 1) - m.nodes(i, 1);
  return s / static_cast<double>(e.top.size());
}

model::Problem loaded(std::shared_ptr<const model::Model> model, const mesh::Mesh& m, const Ends& e, double f) {
  model::Problem p = model::make_problem(std::move(model));
  model::fix_nodes(p, e.bottom);
  for (int i : e.top) p.external_force(m.dim() * i + 1) = f;
  return p;
}

double slope_through_origin(const std::vector<double>& u, const std::vector<double>& f, bool positive) {
  double fu = 0.0, uu = 0.0;
  for (size_t i = 0; i < f.size(); ++i)
    if ((positive ? f[i] > 0.0 : f[i] < 0.0) && std::isfinite(u[i])) {
      fu += f[i] * u[i];
      uu += u[i] * u[i];
    }
  return uu > 0.0 ? fu / uu : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

ForceDisplacement force_displacement(const mesh::Mesh& mesh, const material::Material& material,
                                     calibrate::Method method, const std::vector<double>& forces) {
  const Ends e = ends(mesh);
  const auto springs = calibrate::make_model(mesh, calibrate::calibrate(mesh, {material}, method));
  auto fem = fem::linear_model(mesh, {material});
  ForceDisplacement out;
  for (double f : forces) {
    const solve::StaticResult s = solve::static_equilibrium(loaded(springs, mesh, e, f));
    const solve::StaticResult l = solve::linear_static(loaded(fem, mesh, e, f));
    out.force.push_back(f);
    out.status.emplace_back(solve::status_name(s.report.status));
    out.spring_displacement.push_back(s.report.status == solve::SolveStatus::kConverged
                                          ? mean_top_y(mesh, e, s.positions)
                                          : std::numeric_limits<double>::quiet_NaN());
    out.fem_displacement.push_back(mean_top_y(mesh, e, l.positions));
  }
  out.stretch_stiffness = slope_through_origin(out.spring_displacement, out.force, true);
  out.compress_stiffness = slope_through_origin(out.spring_displacement, out.force, false);
  out.fem_stiffness = slope_through_origin(out.fem_displacement, out.force, true);
  return out;
}

}  // namespace hooke::experiments
