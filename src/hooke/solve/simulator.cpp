#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/solve/detail/integrator_step.hpp>
#include <hooke/solve/simulator.hpp>
#include <string>

namespace hooke::solve {

// The state and loads (detail::SimulationState), the probe, and one integrator family behind
// detail::IntegratorStep (solve/integrators/).
struct Simulator::Impl {
  detail::SimulationState s;
  SimulatorOptions opt;
  std::unique_ptr<detail::IntegratorStep> integrator;
  double time_s = 0.0;
  Probe probe;
  VecX grab_positions;           // positions of the probe nodes' DOFs when grabbed
  std::vector<char> base_fixed;  // fixed DOFs of the problem without the probe

  Impl(model::Problem p, Dynamics d, SimulatorOptions o) : s(std::move(p), std::move(d)), opt(o) {}

  const model::Model& model() const { return s.model(); }

  void update_loads() {
    if (s.problem.external_force.size() == s.nd)
      s.f_total = s.problem.external_force;
    else
      s.f_total.setZero();
    const int d = model().dim();
    if (s.dyn.gravity.size() == d)
      for (Eigen::Index i = 0; i < s.nd; ++i) s.f_total(i) += s.dyn.mass(i) * s.dyn.gravity(i % d);
    if (!probe.nodes.empty() && !probe.drive_position)
      for (int node : probe.nodes)
        s.f_total.segment(d * node, d) += probe.force / static_cast<double>(probe.nodes.size());
  }

  // A driving probe's nodes are fixed DOFs: their targets are grab position + offset.
  void update_probe_targets() {
    if (probe.nodes.empty() || !probe.drive_position) return;
    const int d = model().dim();
    if (s.problem.prescribed_positions.size() != s.nd) s.problem.prescribed_positions = model().rest_positions();
    for (size_t k = 0; k < probe.nodes.size(); ++k)
      s.problem.prescribed_positions.segment(d * probe.nodes[k], d) =
          grab_positions.segment(d * static_cast<Eigen::Index>(k), d) + probe.offset;
  }

  void add_probe_force(StepReport& r) {
    const int d = model().dim();
    r.probe_force.setZero(d);
    if (probe.nodes.empty()) return;
    if (!probe.drive_position) {
      r.probe_force = -probe.force;
      return;
    }
    if (!s.fixed_grad_valid) {
      model().gradient(s.x, s.grad,
                       s.problem.interaction_or_null());  // at the new x: also the next explicit step's gradient
      s.gradient_valid = true;
    }
    const VecX& g = s.fixed_grad_valid ? s.fixed_grad : s.grad;  // the step's own evaluation at x, where it kept one
    for (int node : probe.nodes) r.probe_force -= g.segment(d * node, d) - s.f_total.segment(d * node, d);
  }
};

Simulator::Simulator(model::Problem problem, Dynamics dynamics, SimulatorOptions options)
    : m(std::make_unique<Impl>(std::move(problem), std::move(dynamics), options)) {
  detail::SimulationState& s = m->s;
  const int nd = static_cast<int>(s.nd);
  if (s.problem.fixed_dofs.size() != static_cast<size_t>(nd)) s.problem.fixed_dofs.assign(nd, 0);
  if (s.dyn.mass.size() != nd) throw InvalidArgument("Simulator: the mass vector needs one entry per DOF");
  for (int i = 0; i < nd; ++i)
    if (!s.fixed(i) && !(s.dyn.mass(i) > 0.0))
      throw InvalidArgument("Simulator: free DOF " + std::to_string(i) + " has no mass");
  if (s.dyn.gravity.size() != 0 && s.dyn.gravity.size() != s.model().dim())
    throw InvalidArgument("Simulator: gravity needs one component per axis");
  if (!(s.dyn.mass_damping >= 0.0) || !(s.dyn.stiffness_damping >= 0.0) || !std::isfinite(s.dyn.mass_damping) ||
      !std::isfinite(s.dyn.stiffness_damping))
    throw InvalidArgument("Simulator: Rayleigh damping coefficients must be finite and >= 0");
  if (options.local_global_iterations < 1)
    throw InvalidArgument("Simulator: local-global needs at least 1 iteration per step");
  if (s.dyn.stiffness_damping > 0.0) s.rest_stiffness();
  m->integrator = detail::make_integrator_step(options, s);  // checks the Newton options and the model
  m->base_fixed = s.problem.fixed_dofs;
  s.x = model::initial_positions(s.problem);
  s.model().end_step(s.x);  // history-dependent blocks (lagged friction) start from here
}

Simulator::~Simulator() = default;
Simulator::Simulator(Simulator&&) noexcept = default;
Simulator& Simulator::operator=(Simulator&&) noexcept = default;

StepReport Simulator::step(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt)) throw InvalidArgument("the time step must be a positive number");
  m->update_loads();
  m->update_probe_targets();
  StepReport r = m->integrator->step(m->s, dt);
  m->time_s += dt;
  m->model().end_step(m->s.x);  // the next step starts here: lagged friction freezes its normal forces
  r.linear_iterations = static_cast<int>(m->integrator->linear_iterations());
  m->add_probe_force(r);
  return r;
}

double Simulator::time() const { return m->time_s; }
void Simulator::set_time(double time) {
  if (!std::isfinite(time)) throw InvalidArgument("Simulator::set_time: the time must be finite");
  m->time_s = time;
}
const VecX& Simulator::positions() const { return m->s.x; }
const VecX& Simulator::velocities() const { return m->s.v; }
void Simulator::set_state(const VecX& positions, const VecX& velocities) {
  if (positions.size() != m->s.x.size() || velocities.size() != m->s.v.size())
    throw InvalidArgument("Simulator::set_state: sizes differ from the model's DOF count");
  m->s.x = positions;
  m->s.v = velocities;
  m->s.gradient_valid = false;
  m->s.fixed_grad_valid = false;
}
model::Problem& Simulator::problem() { return m->s.problem; }

void Simulator::set_probe(const Probe& probe) {
  const int d = m->model().dim(), n = m->model().node_count();
  for (int node : probe.nodes)
    if (node < 0 || node >= n) throw InvalidArgument("probe node " + std::to_string(node) + " is not in the model");
  if (!probe.nodes.empty() &&
      ((probe.drive_position && probe.offset.size() != d) || (!probe.drive_position && probe.force.size() != d)))
    throw InvalidArgument("the probe's offset or force needs one component per axis");
  const bool same = probe.nodes == m->probe.nodes && probe.drive_position == m->probe.drive_position;
  if (!same) {
    std::vector<char>& fixed = m->s.problem.fixed_dofs;
    fixed = m->base_fixed;
    m->grab_positions.resize(d * static_cast<Eigen::Index>(probe.nodes.size()));
    for (size_t k = 0; k < probe.nodes.size(); ++k) {
      m->grab_positions.segment(d * static_cast<Eigen::Index>(k), d) = m->s.x.segment(d * probe.nodes[k], d);
      if (probe.drive_position)
        for (int a = 0; a < d; ++a) fixed[static_cast<size_t>(d * probe.nodes[k] + a)] = 1;
    }
    m->s.refix();
    m->s.fixed_grad_valid = false;
    m->integrator->refix();
  }
  m->probe = probe;
}
const Dynamics& Simulator::dynamics() const { return m->s.dyn; }
double Simulator::kinetic_energy() const { return 0.5 * m->s.v.cwiseAbs2().dot(m->s.dyn.mass); }
double Simulator::potential_energy() const {
  m->update_loads();
  return m->model().energy(m->s.x) - m->s.f_total.dot(m->s.x - m->model().rest_positions());
}
VecX Simulator::momentum() const {
  const int d = m->model().dim();
  VecX p = VecX::Zero(d);
  for (Eigen::Index i = 0; i < m->s.x.size(); ++i) p(i % d) += m->s.dyn.mass(i) * m->s.v(i);
  return p;
}
double Simulator::stable_time_step() const { return m->s.stable_dt(); }
const SparseMatrix& Simulator::rest_stiffness() { return m->s.rest_stiffness(); }

}  // namespace hooke::solve
