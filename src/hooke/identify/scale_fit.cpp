#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/identify/positions_objective.hpp>
#include <hooke/identify/scale_fit.hpp>
#include <hooke/mesh/mesh.hpp>
#include <string>

namespace hooke::identify {

calibrate::SpringModel scaled(calibrate::SpringModel springs, double factor) {
  springs.stiffness *= factor;
  springs.volume_stiffness *= factor;
  return springs;
}

ScaleFit fit_scale(const mesh::Mesh& mesh, const calibrate::SpringModel& start, const std::vector<ReferenceCase>& cases,
                   const solve::StaticOptions& statics, int max_iterations) {
  const VecX rest = mesh::flat_positions(mesh);
  for (const ReferenceCase& c : cases) validate_reference(c, rest.size());
  const std::vector<const ReferenceCase*> training = training_cases(cases);
  double g_ref = 0.0;
  for (const ReferenceCase* c : training) g_ref += (c->positions - rest).squaredNorm();
  if (training.empty() || !(g_ref > 0.0))
    throw InvalidArgument("the scale fit needs at least one training case that moves the body");
  ScaleFit out;
  const auto prescribed =
      std::count_if(training.begin(), training.end(), [](const ReferenceCase* c) { return has_prescribed(*c); });
  if (prescribed != 0 && prescribed != static_cast<std::ptrdiff_t>(training.size()))
    throw InvalidArgument(
        "the scale fit takes training cases of one control: all under forces or all with prescribed "
        "positions");
  if (prescribed) {
    // Displacement control: k -> c k leaves every equilibrium where it is and multiplies the held DOFs' forces by c,
    // R(c) = c R(1), so the least-squares c is (R(1) . R_ref) / |R(1)|^2 in one step.
    const auto model = calibrate::make_model(mesh, start);
    double rr = 0.0, r_ref = 0.0, ref_ref = 0.0;
    for (const ReferenceCase* c : training) {
      const solve::StaticResult r = reference_equilibrium(model, *c, statics);
      ++out.static_solves;
      if (r.report.status != solve::SolveStatus::kConverged)
        throw SolverFailure("scale fit, case '" + c->name + "': no equilibrium (" + r.report.message + ")");
      const VecX g = prescribed_part(*c, model->gradient(r.positions));
      const VecX f = prescribed_part(*c, c->external_force);
      rr += g.squaredNorm();
      r_ref += g.dot(f);
      ref_ref += f.squaredNorm();
    }
    if (!(r_ref > 0.0) || !(ref_ref > 0.0))
      throw SolverFailure(
          "scale fit: the model's forces on the prescribed nodes point against the measured ones: no "
          "c > 0 fits");
    out.factor = r_ref / rr;
    out.springs = scaled(start, out.factor);
    out.history = {(rr - 2.0 * r_ref + ref_ref) / ref_ref,
                   (out.factor * out.factor * rr - 2.0 * out.factor * r_ref + ref_ref) / ref_ref};
    out.iterations = 1;
    out.converged = true;
    return out;
  }
  std::vector<VecX> warm(training.size());  // each case's last equilibrium: the next solve's start
  for (int it = 0; it <= max_iterations; ++it) {
    out.springs = scaled(start, out.factor);
    const auto model = calibrate::make_model(mesh, out.springs);
    double uu = 0.0, u_ref = 0.0, g = 0.0;
    for (std::size_t k = 0; k < training.size(); ++k) {
      const ReferenceCase& c = *training[k];
      const solve::StaticResult r = reference_equilibrium(model, c, statics, warm[k]);
      ++out.static_solves;
      if (r.report.status != solve::SolveStatus::kConverged)
        throw SolverFailure("scale fit, case '" + c.name + "' at c = " + std::to_string(out.factor) +
                            ": no equilibrium (" + r.report.message + ")");
      warm[k] = r.positions;
      const VecX u = r.positions - rest, ref = c.positions - rest;
      uu += u.squaredNorm();
      u_ref += u.dot(ref);
      g += (r.positions - c.positions).squaredNorm();
    }
    out.history.push_back(g / g_ref);
    if (out.converged || it == max_iterations) break;
    if (!(u_ref > 0.0))
      throw SolverFailure("scale fit: the model moves against the reference (sum u . u_ref <= 0): no c > 0 fits");
    // Linear about the current c: u(c') = u(c) c / c', whose best c' is c |u|^2 / (u . u_ref).
    const double next = out.factor * uu / u_ref;
    out.converged = std::abs(next / out.factor - 1.0) < 1e-9;
    out.factor = next;
    ++out.iterations;
  }
  return out;
}

}  // namespace hooke::identify
