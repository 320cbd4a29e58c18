#include <algorithm>
#include <cmath>
#include <cstdio>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/core/error.hpp>
#include <hooke/experiments/compare.hpp>
#include <hooke/experiments/term_law_fit.hpp>
#include <limits>
#include <map>
#include <utility>

namespace hooke::experiments {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Where the exponents are searched (inside validate_model's [-8, 8]).
constexpr std::pair<double, double> kSpringRange{-4.0, 4.0}, kVolumeRange{-6.0, 4.0};

void require_fittable(const calibrate::CalibratedModel& model, const TermLawFitOptions& o) {
  if (!(o.strain_range > 0.0 && o.strain_range <= 0.5))
    throw InvalidArgument("the strain range must be in (0, 0.5], not " + std::to_string(o.strain_range));
  if (o.loads.empty()) throw InvalidArgument("fit_term_law: no load case");
  if (o.refinements < 0) throw InvalidArgument("fit_term_law: refinements must be >= 0");
  if (model.surface || calibrate::model_kind(model) == calibrate::ModelKind::kFem)
    throw InvalidArgument("a term law is fitted to spring models only, not to '" + model.method + "'");
}

// The FEM references at S/2 and S, each checked.
std::vector<Reference> references(const calibrate::CalibratedModel& model, const TermLawFitOptions& o) {
  std::vector<Reference> out;
  for (double strain : {0.5 * o.strain_range, o.strain_range}) {
    CompareOptions co;
    co.reference = o.law;
    co.control = model::LoadControl::kDisplacement;
    co.strain = strain;
    for (Reference& r : fem_references(model, o.loads, co)) {
      if (r.fem.report.status != solve::SolveStatus::kConverged)
        throw SolverFailure("the " + std::string(material::law_name(o.law)) + " FEM has no stable equilibrium at " +
                            std::to_string(strain) + " " + std::string(model::load_kind_name(r.load.kind)) + ": " +
                            r.fem.report.message);
      out.push_back(std::move(r));
    }
  }
  return out;
}

// Worst case of `model` against `refs`: max of relative L2 and force error, +infinity where a solve fails. With
// `starts` (one per reference, or empty) Newton starts from them; `solutions` receives the equilibria when all hold.
double worst_error(const calibrate::CalibratedModel& model, const std::vector<Reference>& refs,
                   const std::vector<VecX>& starts = {}, std::vector<VecX>* solutions = nullptr) {
  CompareOptions co;
  double worst = 0.0;
  std::vector<VecX> found;
  for (Comparison& c : compare_to_references(model, refs, co, starts)) {
    if (c.spring_report.status != solve::SolveStatus::kConverged) return kInfinity;
    worst = std::max({worst, c.relative_l2, c.reaction_error});
    found.push_back(std::move(c.spring_positions));
  }
  if (solutions) *solutions = std::move(found);
  return worst;
}

}  // namespace

double term_law_error(const calibrate::CalibratedModel& model, const TermLawFitOptions& options) {
  require_fittable(model, options);
  return worst_error(model, references(model, options));
}

TermLawFit fit_term_law(const calibrate::CalibratedModel& model, const TermLawFitOptions& options) {
  require_fittable(model, options);
  const std::vector<Reference> refs = references(model, options);
  calibrate::CalibratedModel trial = model;
  std::map<std::pair<double, double>, double> seen;
  // The pattern search's laws are neighbours: each is solved from the equilibria of the best law so far (Newton at
  // the full press first; load steps from rest only where that fails), which halves the fit's time.
  std::vector<VecX> best_solutions;
  double best_seen = kInfinity;  // the smallest error measured so far, whose equilibria best_solutions holds
  auto error_at = [&](double m, double q) {
    m = std::clamp(m, kSpringRange.first, kSpringRange.second);
    q = std::clamp(q, kVolumeRange.first, kVolumeRange.second);
    if (const auto it = seen.find({m, q}); it != seen.end()) return it->second;
    trial.springs.spring_exponent = m;
    trial.springs.volume_exponent = q;
    double e = kInfinity;
    std::vector<VecX> solutions;
    try {
      e = worst_error(trial, refs, best_solutions, &solutions);
    } catch (const SolverFailure&) {  // no equilibrium reached: this law does not hold there
    }
    seen[{m, q}] = e;
    if (e < kInfinity && e <= best_seen) {
      best_seen = e;
      best_solutions = std::move(solutions);
    }
    return e;
  };
  TermLawFit fit;
  fit.hookean_error = error_at(1.0, 1.0);
  double best_m = 1.0, best_q = 1.0, best = fit.hookean_error;
  // The coarse grid. Laws that stiffen in compression (Neo-Hookean, and linear's rotation-free response): Hookean,
  // log (m = 0) and inverse (m = -1) springs beside quadratic, log and barrier volumes. St. Venant-Kirchhoff, which
  // stiffens in stretch and softens in compression: Green-strain springs (m = 2, Kikuuwe et al.'s edge StVK) and
  // beyond, with volume laws from softening (q = 2) to the log.
  const bool green = options.law == material::Law::kStVK;
  for (double m : green ? std::vector<double>{3.0, 2.0, 1.0} : std::vector<double>{1.0, 0.0, -1.0})
    for (double q : green ? std::vector<double>{2.0, 1.0, 0.0, -1.0} : std::vector<double>{1.0, 0.0, -1.0, -2.0})
      if (const double e = error_at(m, q); e < best) std::tie(best, best_m, best_q) = std::tuple(e, m, q);
  // Pattern search from the best grid point: move while a neighbour improves, then halve the step (from 1/2, the
  // number of steps options.refinements: 3 ends at 1/8).
  for (int level = 0; level < options.refinements; ++level) {
    const double step = std::ldexp(0.5, -level);
    for (bool moved = true; moved;) {
      moved = false;
      for (const auto& [dm, dq] :
           std::vector<std::pair<double, double>>{{step, 0.0}, {-step, 0.0}, {0.0, step}, {0.0, -step}}) {
        const double m = std::clamp(best_m + dm, kSpringRange.first, kSpringRange.second);
        const double q = std::clamp(best_q + dq, kVolumeRange.first, kVolumeRange.second);
        if (const double e = error_at(m, q); e < best) {
          std::tie(best, best_m, best_q) = std::tuple(e, m, q);
          moved = true;
        }
      }
    }
  }
  fit.spring_exponent = best_m;
  fit.volume_exponent = best_q;
  fit.worst_error = best;
  fit.evaluations = static_cast<int>(seen.size());
  char line[320];
  std::snprintf(line, sizeof line,
                "term law fitted to the %s FEM up to %.3g strain (displacement-controlled %zu cases at %.3g and "
                "%.3g): spring exponent %.4g, volume exponent %.4g, worst error %.4g (Hookean %.4g), %d laws measured",
                std::string(material::law_name(options.law)).c_str(), options.strain_range, refs.size(),
                0.5 * options.strain_range, options.strain_range, best_m, best_q, best, fit.hookean_error,
                fit.evaluations);
  fit.summary = line;
  return fit;
}

calibrate::CalibratedModel with_fitted_law(calibrate::CalibratedModel model, const TermLawFitOptions& options) {
  const TermLawFit fit = fit_term_law(model, options);
  model.springs.spring_exponent = fit.spring_exponent;
  model.springs.volume_exponent = fit.volume_exponent;
  model.choice += (model.choice.empty() ? "" : "; ") + fit.summary;
  return model;
}

calibrate::CalibratedModel choose_for_range(const calibrate::CalibratedModel& picked,
                                            const TermLawFitOptions& options) {
  std::vector<std::string> methods{picked.method};
  const std::vector<std::string> any_nu = picked.mesh.kind == mesh::ElementKind::kTet
                                              ? std::vector<std::string>{"stiffness-fit-volume", "any-nu-tet"}
                                              : std::vector<std::string>{"any-nu-triangle"};
  for (const std::string& m : any_nu)
    if (std::find(methods.begin(), methods.end(), m) == methods.end()) methods.push_back(m);
  calibrate::CalibratedModel best;
  double best_error = kInfinity;
  std::string measured;
  for (const std::string& method : methods) {
    calibrate::CalibratedModel candidate = picked;
    if (method != picked.method) {
      calibrate::ModelOptions mo;
      mo.method = method;
      mo.density = picked.density;
      mo.regions = picked.regions;
      candidate = calibrate::calibrate_model(picked.mesh, picked.material, mo);
      candidate.meshing = picked.meshing;
    }
    const TermLawFit fit = fit_term_law(candidate, options);
    char line[160];
    std::snprintf(line, sizeof line, "%s%s %.3g (Hookean %.3g, m %.4g, q %.4g)", measured.empty() ? "" : ", ",
                  method.c_str(), fit.worst_error, fit.hookean_error, fit.spring_exponent, fit.volume_exponent);
    measured += line;
    if (fit.worst_error < best_error) {
      best_error = fit.worst_error;
      best = std::move(candidate);
      best.springs.spring_exponent = fit.spring_exponent;
      best.springs.volume_exponent = fit.volume_exponent;
    }
  }
  if (!(best_error < kInfinity))
    throw SolverFailure("no candidate model has a stable equilibrium on every case up to " +
                        std::to_string(options.strain_range) + " strain: " + measured);
  char head[200];
  std::snprintf(head, sizeof head,
                "auto over a strain range: the smallest worst case (relative L2 and force error, displacement-"
                "controlled, against the %s FEM at %.3g and %.3g strain) after each model's term law was fitted: ",
                std::string(material::law_name(options.law)).c_str(), 0.5 * options.strain_range, options.strain_range);
  best.choice = head + measured + "; small-strain pick: " + picked.choice;
  return best;
}

}  // namespace hooke::experiments
