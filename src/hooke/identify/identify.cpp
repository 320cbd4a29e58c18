#include <chrono>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/log.hpp>
#include <hooke/core/name_table.hpp>
#include <hooke/identify/identify.hpp>
#include <hooke/identify/positions_objective.hpp>
#include <hooke/identify/scale_fit.hpp>
#include <hooke/identify/stacked_forces.hpp>
#include <limits>
#include <memory>

namespace hooke::identify {
namespace {

constexpr NameTable<Objective, 2> kObjectives{"identification objective",
                                              {{{Objective::kForces, "forces"}, {Objective::kPositions, "positions"}}}};

// [A; W (theta_g - mean theta_g)]: Lloyd's penalty toward the mean stiffness (Sec. 2), per group of unknowns.
class RegularisedOperator final : public LinearOperator {
 public:
  struct Group {
    Eigen::Index begin, size;
    double weight;
  };
  RegularisedOperator(const LinearOperator& a, std::vector<Group> groups) : m_a(a), m_groups(std::move(groups)) {
    for (const auto& g : m_groups) m_extra += g.size;
  }
  Eigen::Index rows() const override { return m_a.rows() + m_extra; }
  Eigen::Index cols() const override { return m_a.cols(); }
  void apply(const VecX& x, VecX& y) const override {
    VecX head;
    m_a.apply(x, head);
    y.resize(rows());
    y.head(m_a.rows()) = head;
    Eigen::Index row = m_a.rows();
    for (const auto& g : m_groups) {
      const auto part = x.segment(g.begin, g.size);
      y.segment(row, g.size) = g.weight * (part.array() - part.mean()).matrix();
      row += g.size;
    }
  }
  void apply_transpose(const VecX& y, VecX& x) const override {
    m_a.apply_transpose(y.head(m_a.rows()), x);
    Eigen::Index row = m_a.rows();
    for (const auto& g : m_groups) {  // (I - 1 1^T / n) is symmetric
      const auto part = y.segment(row, g.size);
      x.segment(g.begin, g.size) += g.weight * (part.array() - part.mean()).matrix();
      row += g.size;
    }
  }
  VecX squared_column_norms() const override {
    VecX out = m_a.squared_column_norms();
    for (const auto& g : m_groups)
      out.segment(g.begin, g.size).array() += g.weight * g.weight * (1.0 - 1.0 / static_cast<double>(g.size));
    return out;
  }

 private:
  const LinearOperator& m_a;
  std::vector<Group> m_groups;
  Eigen::Index m_extra = 0;
};

std::vector<const ReferenceCase*> fitted_cases(const std::vector<ReferenceCase>& cases, const ReferenceCase& rest,
                                               bool with_rest) {
  std::vector<const ReferenceCase*> out = training_cases(cases);
  if (out.empty()) throw InvalidArgument("identification needs at least one reference case that is not held out");
  if (with_rest) out.push_back(&rest);
  return out;
}

// Eq. 2 on `layout`: returns theta; fills the least-squares report.
VecX fit_forces(const ParameterLayout& layout, const std::vector<const ReferenceCase*>& cases,
                const IdentifyOptions& options, const VecX& lower, const VecX& start,
                BoundedLeastSquaresReport& report) {
  const StackedForceOperator stacked(layout, cases);
  const VecX b = stacked.right_hand_side(cases);
  std::vector<RegularisedOperator::Group> groups;
  if (options.regularization > 0.0) {
    const VecX norms = stacked.squared_column_norms();
    const auto add = [&](Eigen::Index begin, Eigen::Index size) {
      if (size < 2) return;
      const double rms = std::sqrt(norms.segment(begin, size).mean());
      if (rms > 0.0) groups.push_back({begin, size, options.regularization * rms});
    };
    add(0, layout.spring_count());
    add(layout.spring_count(), layout.volume_count());
  }
  const RegularisedOperator a(stacked, groups);
  VecX bb = VecX::Zero(a.rows());
  bb.head(b.size()) = b;
  return solve_bounded_least_squares(a, bb, lower, start, options.least_squares, &report);
}

// Eq. 2 with every spring kept at or above stiffness_floor x the mean k. With a start model, the fit starts from
// its parameters and the mean is its mean k. Without one, the mean comes from a rough first fit (tolerance 1e-2: a
// mean is settled long before the single springs are), then the fit itself with the floor.
VecX fit_forces_with_floor(const ParameterLayout& layout, const std::vector<const ReferenceCase*>& cases,
                           const IdentifyOptions& options, BoundedLeastSquaresReport& report) {
  VecX lower = layout.lower_bounds();
  const int ns = layout.spring_count();
  VecX start;
  if (options.start_model && layout.offset_count() == 0) start = parameters_of(layout, *options.start_model);
  if (ns == 0 || !(options.stiffness_floor > 0.0)) return fit_forces(layout, cases, options, lower, start, report);
  if (start.size() && start.head(ns).mean() > 0.0) {
    lower.head(ns).setConstant(options.stiffness_floor * start.head(ns).mean());
    return fit_forces(layout, cases, options, lower, start.cwiseMax(lower), report);
  }
  IdentifyOptions rough = options;
  rough.least_squares.tolerance = std::max(options.least_squares.tolerance, 1e-2);
  BoundedLeastSquaresReport first;
  VecX theta = fit_forces(layout, cases, rough, lower, {}, first);
  lower.head(ns).setConstant(options.stiffness_floor * theta.head(ns).mean());
  theta = fit_forces(layout, cases, options, lower, theta, report);
  report.iterations += first.iterations;  // the work of both solves
  report.cg_iterations += first.cg_iterations;
  report.products += first.products;
  return theta;
}

// |f_ref - U theta| / |f_ref| over the free DOFs of `cases`.
double relative_force_residual(const ParameterLayout& layout, const VecX& theta,
                               const std::vector<const ReferenceCase*>& cases) {
  const StackedForceOperator a(layout, cases);
  const VecX b = a.right_hand_side(cases);
  VecX r;
  a.apply(theta, r);
  const double scale = b.norm();
  return scale > 0.0 ? (r - b).norm() / scale : (r - b).norm();
}

// Eq. 1's start: the Eq. 2 fit `start` or options.start_model, whichever has the smaller G, within the bounds and
// with the springs at or above `floor`; g and gradient are G and its gradient there.
VecX positions_start(PositionsObjective& objective, const ParameterLayout& layout, const VecX& start, double floor,
                     const IdentifyOptions& options, IdentifyReport& report, double& g, VecX& gradient) {
  const int ns = layout.spring_count();
  const VecX lower = layout.lower_bounds();
  const auto within_bounds = [&](VecX theta) {
    theta = theta.cwiseMax(lower);
    theta.head(ns) = theta.head(ns).cwiseMax(floor);
    return theta;
  };
  VecX theta = within_bounds(start);
  g = objective.value(theta, &gradient);
  report.eq2_positions_objective = g;
  if (options.start_model) {
    const VecX theta_model = within_bounds(parameters_of(layout, *options.start_model));
    VecX gradient_model;
    const double g_model = objective.value(theta_model, &gradient_model);
    report.start_model_objective = g_model;
    if (g_model < g || !std::isfinite(g)) {
      theta = theta_model;
      g = g_model;
      gradient = gradient_model;
      report.started_from_model = true;
    }
  }
  if (!std::isfinite(g)) throw SolverFailure("identification: the start has no stable equilibrium on a training case");
  return theta;
}

// Eq. 1's variable scale s (theta = s .* z), s = |theta| (the group's mean magnitude where it is 0), so that |z| ~ 1.
// Where every k_V is 0 the scale is 0.1 x the springs' mean k L^2, a tenth of the strain energy a spring carries
// ((tr eps)^2 k_V/2 against (eps_s L)^2 k/2). On cylinder_hole at nu = 0 with negative volume terms, G after 15
// iterations was 0.0201 with 1, 0.0106 with 0.1, 0.0111 with 0.01 (the terms barely move) and with them frozen.
VecX positions_scale(const ParameterLayout& layout, const VecX& theta) {
  const int ns = layout.spring_count();
  VecX s = theta.cwiseAbs();
  double volume_scale = s.size() > ns ? s.tail(s.size() - ns).mean() : 1.0;
  if (!(volume_scale > 0.0) && ns > 0)
    volume_scale = 0.1 * theta.head(ns).cwiseProduct(layout.rest_length.cwiseAbs2()).mean();
  volume_scale = std::max(volume_scale, 1e-30);
  for (Eigen::Index j = 0; j < s.size(); ++j)
    if (!(s(j) > 0.0)) s(j) = j < ns ? s.head(ns).mean() : volume_scale;
  return s;
}

// Eq. 1 by spectral projected gradients (Birgin, Martinez & Raydan 2000) in the scaled variables, with a
// non-monotone Armijo search over the last 5 values.
VecX fit_positions(const mesh::Mesh& mesh, const ParameterLayout& layout, const std::vector<ReferenceCase>& cases,
                   const VecX& start, const IdentifyOptions& options, IdentifyReport& report) {
  std::vector<ReferenceCase> training;
  for (const ReferenceCase* c : training_cases(cases)) training.push_back(*c);
  PositionsObjective objective(mesh, layout, training, options.statics);
  const int ns = layout.spring_count();
  const double floor = options.stiffness_floor * start.head(ns).mean();
  double g = 0.0;
  VecX gradient;
  const VecX theta = positions_start(objective, layout, start, floor, options, report, g, gradient);
  const VecX s = positions_scale(layout, theta);
  VecX z_lower = layout.lower_bounds().cwiseQuotient(s);  // 0 or -infinity
  z_lower.head(ns) = floor * s.head(ns).cwiseInverse();
  VecX z = theta.cwiseQuotient(s), gz = gradient.cwiseProduct(s);
  report.position_history.push_back(g);
  std::vector<double> recent{g};
  const auto projected_gradient = [&](const VecX& zz, const VecX& gg) {
    return (zz - (zz - gg).cwiseMax(z_lower)).norm();
  };
  const double pg0 = std::max(projected_gradient(z, gz), std::numeric_limits<double>::min());
  double alpha = 1.0 / std::max(gz.lpNorm<Eigen::Infinity>(), std::numeric_limits<double>::min()) * 0.1;
  for (report.position_iterations = 0; report.position_iterations < options.position_iterations;
       ++report.position_iterations) {
    if (projected_gradient(z, gz) <= options.position_tolerance * pg0) {
      report.converged = true;
      break;
    }
    const VecX d = (z - alpha * gz).cwiseMax(z_lower) - z;
    const double reference = *std::max_element(recent.begin(), recent.end());
    double step = 1.0, g_new = 0.0;
    VecX z_new, grad_new;
    bool accepted = false;
    for (int halving = 0; halving < 20; ++halving, step *= 0.5) {
      z_new = z + step * d;
      g_new = objective.value(z_new.cwiseProduct(s), &grad_new);
      if (std::isfinite(g_new) && g_new <= reference + 1e-4 * step * gz.dot(d)) {
        accepted = true;
        break;
      }
    }
    if (!accepted) break;
    const VecX gz_new = grad_new.cwiseProduct(s);
    const VecX dz = z_new - z, dg = gz_new - gz;
    const double sy = dz.dot(dg);
    alpha = sy > 0.0 ? std::clamp(dz.squaredNorm() / sy, 1e-10, 1e10) : 1e10;
    z = z_new;
    gz = gz_new;
    g = g_new;
    report.position_history.push_back(g);
    recent.push_back(g);
    if (recent.size() > 5) recent.erase(recent.begin());
  }
  report.static_solves = objective.static_solves();
  return z.cwiseProduct(s);
}

}  // namespace

Objective objective_from_name(std::string_view name) { return kObjectives.from_name(name); }
std::string_view objective_name(Objective objective) { return kObjectives.name(objective); }

double force_residual(const ParameterLayout& layout, const VecX& theta, const std::vector<ReferenceCase>& cases) {
  std::vector<const ReferenceCase*> all;
  for (const auto& c : cases) all.push_back(&c);
  return relative_force_residual(layout, theta, all);
}

namespace {

// Parameters::kScale: one factor on the start model (scale_fit.hpp), reported like an Eq. 1 fit.
Identification identify_scale(const mesh::Mesh& mesh, const std::vector<ReferenceCase>& cases,
                              const IdentifyOptions& options, std::chrono::steady_clock::time_point t0) {
  if (!options.start_model)
    throw InvalidArgument("identification parameters 'scale' scale a start model: give one (hooke identify --compare)");
  const ScaleFit fit = fit_scale(mesh, *options.start_model, cases, options.statics, options.position_iterations);
  Identification out;
  const bool volume = fit.springs.volume_tets.rows() != 0 && mesh.kind == mesh::ElementKind::kTet;
  out.layout = parameter_layout(mesh, volume ? Parameters::kSpringsVolume : Parameters::kSprings);
  out.theta = parameters_of(out.layout, fit.springs);
  out.springs = fit.springs;
  IdentifyReport& r = out.report;
  r.position_iterations = fit.iterations;
  r.static_solves = fit.static_solves;
  r.position_history = fit.history;
  r.start_model_objective = fit.history.front();
  r.started_from_model = true;
  r.converged = fit.converged;
  r.scale_factor = fit.factor;
  const std::vector<const ReferenceCase*> training = training_cases(cases);
  r.force_residual = relative_force_residual(out.layout, out.theta, training);
  if (out.springs.stiffness.size()) {
    r.min_stiffness = out.springs.stiffness.minCoeff();
    r.max_stiffness = out.springs.stiffness.maxCoeff();
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace

void validate_options(const IdentifyOptions& options) {
  if (!(options.least_squares.tolerance > 0.0 && options.least_squares.tolerance < 1.0))
    throw InvalidArgument("identification: the Eq. 2 tolerance must be in (0, 1), got " +
                          std::to_string(options.least_squares.tolerance));
  if (!(options.regularization >= 0.0) || !std::isfinite(options.regularization))
    throw InvalidArgument("identification: the regularization weight must be a finite number >= 0, got " +
                          std::to_string(options.regularization));
  if (!(options.stiffness_floor >= 0.0 && options.stiffness_floor < 1.0))
    throw InvalidArgument("identification: the stiffness floor must be in [0, 1) of the mean k, got " +
                          std::to_string(options.stiffness_floor));
  if (options.position_iterations < 0)
    throw InvalidArgument("identification: the Eq. 1 iterations must be >= 0, got " +
                          std::to_string(options.position_iterations));
}

Identification identify(const mesh::Mesh& mesh, const std::vector<ReferenceCase>& cases,
                        const IdentifyOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  validate_options(options);
  if (options.parameters == Parameters::kScale) return identify_scale(mesh, cases, options, t0);
  const VecX rest_positions = mesh::flat_positions(mesh);
  for (const auto& c : cases) validate_reference(c, rest_positions.size());
  const ReferenceCase rest{
      "rest", rest_positions, VecX::Zero(rest_positions.size()), std::vector<char>(rest_positions.size(), 0), false,
      {}};
  const bool rest_lengths = options.parameters == Parameters::kSpringsVolumeRestLength;
  const auto training = fitted_cases(cases, rest, rest_lengths);

  Identification out;
  out.layout = parameter_layout(mesh, options.parameters);
  out.layout.negative_volume = options.negative_volume;
  if (options.start_model) {  // the start's term law: the identified constants are of the same law
    out.layout.spring_exponent = options.start_model->spring_exponent;
    out.layout.volume_exponent = options.start_model->volume_exponent;
    if (out.layout.spring_exponent != 1.0 && rest_lengths)
      throw InvalidArgument(
          "identification: rest lengths are fitted for Hookean springs only (the start model's "
          "springs have the large-strain law m = " +
          std::to_string(out.layout.spring_exponent) + ")");
    if (out.layout.volume_exponent != 1.0 && options.negative_volume)
      throw InvalidArgument(
          "identification: negative volume terms keep the quadratic law; the start model's law "
          "has q = " +
          std::to_string(out.layout.volume_exponent));
  }
  out.theta = fit_forces_with_floor(out.layout, training, options, out.report.least_squares);
  if (rest_lengths) {  // fold the offsets into rest lengths, then refit k and k_V with them
    const calibrate::SpringModel fitted = spring_model(out.layout, out.theta, &out.report.clamped_rest_lengths);
    out.layout.parameters = Parameters::kSpringsVolume;
    out.layout.rest_length = fitted.rest_length;
    out.theta = fit_forces_with_floor(out.layout, training, options, out.report.least_squares);
  }
  out.report.converged = out.report.least_squares.converged;
  if (options.objective == Objective::kPositions) {
    out.report.converged = false;
    out.theta = fit_positions(mesh, out.layout, cases, out.theta, options, out.report);
  }
  out.report.force_residual = relative_force_residual(out.layout, out.theta, training);
  out.springs = spring_model(out.layout, out.theta);
  if (out.layout.spring_count()) {
    out.report.min_stiffness = out.springs.stiffness.minCoeff();
    out.report.max_stiffness = out.springs.stiffness.maxCoeff();
  }
  out.report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace hooke::identify
