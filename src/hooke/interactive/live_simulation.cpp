#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/symmetric_eigen.hpp>
#include <hooke/interactive/latest_job.hpp>
#include <hooke/interactive/live_simulation.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/solve/node_compliance.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <hooke/solve/tool_press.hpp>
#include <numeric>
#include <string>

namespace hooke::interactive {
namespace {

void check_settings(const LiveSettings& s) {
  solve::validate(s.dynamics);
  if (!(s.model.density > 0.0) || !std::isfinite(s.model.density))
    throw InvalidArgument("the density must be > 0 kg/m^3");
}

bool same_surface(const calibrate::SurfaceOptions& a, const calibrate::SurfaceOptions& b) {
  return a.scheme == b.scheme && a.centre == b.centre && a.membrane_thickness == b.membrane_thickness &&
         a.anchor_law == b.anchor_law && a.volume_penalty == b.volume_penalty && a.volume_force == b.volume_force &&
         a.shear_factor == b.shear_factor;
}

calibrate::CalibratedModel calibrate_for(const mesh::Mesh& mesh, const LiveSettings& s) {
  return calibrate::calibrate_model(mesh, s.material, s.model);
}

// The holding force: sum over the grabbed nodes of -(dE/dx - f), N.
VecX holding_force(const model::Problem& problem, const VecX& x, const std::vector<int>& grabbed) {
  const int d = problem.model->dim();
  const VecX g = problem.model->gradient(x, problem.interaction_or_null()) - problem.external_force;
  VecX f = VecX::Zero(d);
  for (const int node : grabbed) f -= g.segment(d * node, d);
  return f;
}

}  // namespace

struct LiveSimulation::Impl {
  LiveSettings settings;
  calibrate::CalibratedModel model;
  calibrate::BuiltModel built;
  std::vector<int> clamped;
  std::optional<solve::Simulator> sim;
  std::optional<model::Interaction> interaction;
  long model_version = 0;
  solve::Probe probe;
  VecX grab_positions, offset, force;
  MatX contact_stiffness;  // of the grabbed nodes (empty: not computed since the grab or the rebuild)
  MatX curvature;          // the condensed energy's third derivative, with it (empty: none, or not wanted)
  long steps = 0;          // since the rebuild, for HapticModel::version
  // The secant stiffness and the probe's offset and force after the previous step (empty: none since the grab).
  MatX secant;
  VecX last_offset, last_force;
  // The tool: its shape and pose (shared with the contact block the simulator's model holds), the block, the state
  // reported after each step.
  std::shared_ptr<contact::RigidTool> tool;
  std::shared_ptr<contact::ContactBlock> contact;
  double tool_friction = 0.0;  // its Coulomb coefficient
  std::optional<LiveTool> tool_state;
  contact::Pose tool_origin;  // where set_tool put it: a device's offset counts from here
  // The body's compliance at surface nodes, for the tool's local contact model (made at its first use per model).
  std::optional<solve::NodeCompliance> compliance;

  void forget_local_model() {
    local_job->drop();
    contact_stiffness.resize(0, 0);
    curvature.resize(0, 0);
    secant.resize(0, 0);
    last_offset.resize(0);
    last_force.resize(0);
  }

  // The grab's local model: what makes it, copied, so that it can be made in another thread while this one steps
  // (the model is immutable and its evaluations thread-safe, docs/architecture.md; a tool's pose is not, so with a
  // tool the curvature is taken here when the stiffness arrives).
  struct LocalModelInput {
    SparseMatrix stiffness;  // the rest stiffness
    std::vector<char> clamp;
    VecX rest, positions;
    int dim = 3;
    std::vector<int> nodes;
    solve::ContactStiffnessOptions region;
    std::shared_ptr<const model::Model> model;  // null: no curvature
    std::optional<model::Interaction> interaction;
    double size = 0.0;  // the body's bounding-box diagonal, m
  };
  struct LocalModel {
    MatX stiffness, curvature, modes;
    bool with_curvature = false;  // the curvature was taken (LocalModelInput::model given)
  };

  // The curvature where the body is now (the grab); a difference step of 1e-4 of the body's size, 1e-6 where an
  // element inverts within that, and none (the linear model, HapticModel::curvature empty) where it inverts within
  // 1e-6 too: the body is nearly crushed there, and a grab must not stop the simulation.
  static MatX curvature_at(const model::Model& model, const VecX& x, const MatX& modes, double size,
                           const model::Interaction* interaction) {
    for (const double step : {1e-4, 1e-6}) {
      try {
        return solve::contact_curvature(model, x, modes, step * size, interaction);
      } catch (const SolverFailure&) {
      }
    }
    return {};
  }

  static LocalModel make_local_model(const LocalModelInput& in) {
    solve::ContactResponse r = solve::contact_response(in.stiffness, in.clamp, in.rest, in.dim, in.nodes, in.region);
    LocalModel out{std::move(r.stiffness), MatX(), std::move(r.modes), in.model != nullptr};
    if (in.model)
      out.curvature =
          curvature_at(*in.model, in.positions, out.modes, in.size, in.interaction ? &*in.interaction : nullptr);
    return out;
  }

  LocalModelInput local_model_input(bool curvature_too) {
    const int d = dim();
    LocalModelInput in;
    in.stiffness = sim->rest_stiffness();
    in.rest = built.model->rest_positions();
    // The body as the clamp holds it (the simulator's fixed DOFs also hold the grabbed nodes).
    in.clamp.assign(static_cast<size_t>(in.rest.size()), 0);
    for (const int i : clamped)
      for (int a = 0; a < d; ++a) in.clamp[static_cast<size_t>(d * i + a)] = 1;
    in.positions = sim->positions();
    in.dim = d;
    in.nodes = probe.nodes;
    in.region = settings.haptic_region;
    if (curvature_too) in.model = built.model;
    in.interaction = interaction;
    in.size = mesh::bounding_box_diagonal(model.mesh);
    return in;
  }

  void keep(LocalModel&& local) {
    contact_stiffness = std::move(local.stiffness);
    curvature = std::move(local.curvature);
    if (settings.haptic_curvature && !local.with_curvature)  // a tool's: not taken beside the stepping
      curvature = curvature_at(*built.model, sim->positions(), local.modes, mesh::bounding_box_diagonal(model.mesh),
                               interaction_or_null());
  }

  bool background_local_model = false;  // make the local model in a thread of its own (set_local_model_in_background)
  // (behind a pointer: apply() moves a whole new Impl in; the old one's destructor waits for a job still running)
  std::unique_ptr<LatestJob<LocalModel>> local_job = std::make_unique<LatestJob<LocalModel>>();

  // Whether the condensed rest stiffness at the grabbed nodes (contact_stiffness, with its curvature) is there: made
  // at the first call after a grab or a rebuild, in this thread, or with background_local_model in a thread of its
  // own, false until it is done (the step goes on meanwhile; at the 11 425-node cylinder it takes 0.9 s).
  bool local_model_ready() {
    if (contact_stiffness.rows() == dim()) return true;
    if (!background_local_model) {
      keep(make_local_model(local_model_input(settings.haptic_curvature)));
      return true;
    }
    if (std::optional<LocalModel> done = local_job->take()) {
      keep(std::move(*done));
      return true;
    }
    if (!local_job->pending())
      local_job->submit([in = local_model_input(settings.haptic_curvature && !tool)] { return make_local_model(in); });
    return false;
  }

  const model::Interaction* interaction_or_null() const { return interaction ? &*interaction : nullptr; }

  // k's symmetric part projected onto the positive semidefinite matrices (a negative stiffness would feed energy
  // into the device): what the local model renders, the secant after its update and the condensed stiffness plus
  // T(offset), its tangent at the offset (the offsets count from the grab, where the curvature is taken).
  static MatX positive_part(const MatX& k) {
    const SymmetricEigen eig = symmetric_eigen(0.5 * (k + k.transpose()));
    return eig.vectors * eig.values.cwiseMax(0.0).asDiagonal() * eig.vectors.transpose();
  }

  // Powell-symmetric-Broyden: the smallest symmetric change of K with K s = y, s the probe's move over the step and
  // y minus the force's change; only for moves of at least 1 um along which the body pushed back (y . s > 0), then
  // projected onto the positive semidefinite matrices (a negative stiffness would feed energy into the device).
  // With a curvature T the secant is the tangent at the last offset: the pair's y less the quadratic part T(s, s) / 2
  // updates it there, and T(s) carries it to the new offset.
  void update_secant() {
    const int d = dim();
    if (secant.rows() != d) {
      if (!local_model_ready()) {  // the pairs start with the stiffness they update
        last_offset = offset;
        last_force = force;
        return;
      }
      secant = contact_stiffness;
    }
    if (last_offset.size() == d) {
      const VecX s = offset - last_offset;
      VecX y = -(force - last_force);
      MatX shift = MatX::Zero(d, d);
      if (curvature.rows() == d) {
        shift = curvature_along(curvature, s);
        y -= 0.5 * shift * s;
      }
      const double ss = s.squaredNorm();
      if (s.norm() >= 1e-6 && y.dot(s) > 0.0) {
        const VecX r = y - secant * s;
        secant += (r * s.transpose() + s * r.transpose()) / ss - (r.dot(s) / (ss * ss)) * (s * s.transpose());
      }
      secant = positive_part(secant + shift);
    }
    last_offset = offset;
    last_force = force;
  }

  int dim() const { return model.mesh.dim(); }

  // Builds the simulator for the current model and settings at state (x, v) and time t; re-grabs the probe's nodes
  // where they are, keeping their target.
  void rebuild(const VecX& x, const VecX& v, double t) {
    const int d = dim();
    forget_local_model();
    compliance.reset();
    // With a tool, the simulator's model is the body's terms and the contact block (its stiffness from the current
    // E); `built`, which drawing threads share, stays the body's alone.
    std::shared_ptr<model::Model> simulated = built.model;
    if (tool) {
      contact = contact::boundary_contact(model.mesh, model.material.youngs_modulus, tool);
      contact->set_friction({tool_friction, contact::default_creep_velocity(mesh::bounding_box_diagonal(model.mesh)) *
                                                settings.dynamics.dt});
      simulated = calibrate::build_model(model).model;
      simulated->add(std::make_unique<contact::ContactBlock>(*contact));
    }
    model::Problem problem = model::make_problem(simulated);
    clamped.clear();
    if (!model.surface) {
      clamped = model::make_load_case(model.mesh, model::LoadKind::kStretch, 0.0, model.material.thickness).fixed_nodes;
      model::fix_nodes(problem, clamped);
    }
    solve::Simulator s(std::move(problem), solve::make_dynamics(settings.dynamics, model.masses, d),
                       settings.simulator);  // checks the integrator's options
    s.set_state(x, v);
    s.set_time(t);
    sim.emplace(std::move(s));
    if (!probe.nodes.empty()) {
      // The driven nodes sit at grab position + offset: grab them there, with the offset from now on zero.
      for (size_t k = 0; k < probe.nodes.size(); ++k)
        grab_positions.segment(d * static_cast<Eigen::Index>(k), d) = x.segment(d * probe.nodes[k], d);
      offset.setZero(d);
      probe.offset = offset;
      sim->set_probe(probe);
      update_interaction();
    }
    if (tool) place_tool(tool->pose());
  }

  // Moves the tool, putting nodes it passed back outside it, and reports its contact at the current state.
  void place_tool(const contact::Pose& pose) {
    const int pushed = solve::move_tool(*sim, *contact, *tool, pose);
    report_tool();
    tool_state->pushed_nodes += pushed;
  }

  void report_tool() {
    if (!tool) {
      tool_state.reset();
      return;
    }
    const int pushed = tool_state ? tool_state->pushed_nodes : 0;
    const VecX& x = sim->positions();
    tool_state = LiveTool{*tool,
                          contact->tool_force(x),
                          contact->active_count(x),
                          contact->smallest_distance(x),
                          contact->activation(),
                          contact->friction().coefficient,
                          pushed};
  }

  // The tool's local contact model at the current state (HapticModel::contact).
  std::shared_ptr<const LocalContact> local_contact() {
    const VecX& x = sim->positions();
    if (!compliance) {
      const VecX& rest = built.model->rest_positions();
      std::vector<char> fixed(static_cast<size_t>(rest.size()), 0);
      for (const int i : clamped)
        for (int a = 0; a < 3; ++a) fixed[static_cast<size_t>(3 * i + a)] = 1;
      compliance.emplace(built.model->hessian(rest), fixed, 3);
    }
    // The boundary nodes within reach, nearest first.
    const double reach = local_contact_reach(*tool, mesh::bounding_box_diagonal(model.mesh), contact->activation());
    const std::vector<int>& boundary = contact->nodes();
    std::vector<std::pair<double, int>> near;  // distance, index in boundary
    for (size_t k = 0; k < boundary.size(); ++k) {
      const double gap = tool->signed_distance(x.segment<3>(3 * boundary[k]));
      if (gap < reach) near.emplace_back(gap, static_cast<int>(k));
    }
    std::sort(near.begin(), near.end());
    if (near.size() > static_cast<size_t>(kLocalContactNodes)) near.resize(static_cast<size_t>(kLocalContactNodes));
    std::vector<int> nodes;
    VecX positions(3 * static_cast<Eigen::Index>(near.size())), kappa(static_cast<Eigen::Index>(near.size()));
    for (size_t j = 0; j < near.size(); ++j) {
      const int node = boundary[static_cast<size_t>(near[j].second)];
      nodes.push_back(node);
      positions.segment<3>(3 * static_cast<Eigen::Index>(j)) = x.segment<3>(3 * node);
      kappa(static_cast<Eigen::Index>(j)) = contact->stiffness()(near[j].second);
    }
    return std::make_shared<const LocalContact>(*tool, std::move(positions), std::move(kappa), contact->activation(),
                                                compliance->block(nodes), tool_state->force);
  }

  // The surface model's Eq. 4 weights follow the probe: p_f at the first grabbed node, F_f along the drag.
  void update_interaction() {
    interaction.reset();
    if (built.volume_penalty && !probe.nodes.empty()) {
      const int d = dim();
      const VecX total = grab_positions.segment(0, d) + offset - model.mesh.nodes.row(probe.nodes[0]).transpose();
      if (total.norm() > 0.0) {
        const double radius = solve::influence_radius(settings.dynamics, mesh::bounding_box_diagonal(model.mesh));
        interaction = model::Interaction{model.mesh.nodes.row(probe.nodes[0]).transpose(), Vec3(total), radius};
      }
    }
    sim->problem().interaction = interaction;
  }

  void reset_state() {
    probe = solve::Probe{};
    grab_positions.resize(0);
    offset.setZero(dim());
    force.setZero(dim());
    const VecX& rest = built.model->rest_positions();
    rebuild(rest, VecX::Zero(rest.size()), 0.0);
    interaction.reset();
    sim->problem().interaction.reset();
  }
};

LiveSimulation::LiveSimulation(const mesh::Mesh& mesh, const LiveSettings& settings) : m(std::make_unique<Impl>()) {
  check_settings(settings);
  m->settings = settings;
  m->model = calibrate_for(mesh, settings);
  m->built = calibrate::build_model(m->model);
  m->reset_state();
}

LiveSimulation::LiveSimulation(calibrate::CalibratedModel model, const LiveSettings& settings)
    : m(std::make_unique<Impl>()) {
  check_settings(settings);
  // "file", or the model's own method (or "auto" for a model "auto" chose) with its own material and density, runs
  // the model as it is.
  const bool same_method =
      settings.model.method == model.method || (settings.model.method == "auto" && !model.choice.empty());
  const bool own = calibrate::model_kind_of_method(settings.model.method) == calibrate::ModelKind::kFile;
  const bool as_is = own || (same_method && settings.material == model.material &&
                             settings.model.density == model.density && settings.model.regions == model.regions);
  if (!as_is) model = calibrate_for(model.mesh, settings);
  m->settings = settings;
  m->built = calibrate::build_model(model);
  m->model = std::move(model);
  m->reset_state();
}

LiveSimulation::~LiveSimulation() = default;
LiveSimulation::LiveSimulation(LiveSimulation&&) noexcept = default;
LiveSimulation& LiveSimulation::operator=(LiveSimulation&&) noexcept = default;

std::string live_method_for(const calibrate::CalibratedModel& model) {
  if (!model.choice.empty()) return "auto";
  const std::vector<std::string> names = calibrate::model_method_names();
  return std::find(names.begin(), names.end(), model.method) != names.end()
             ? model.method
             : std::string(calibrate::model_kind_name(calibrate::ModelKind::kFile));
}

void LiveSimulation::apply(const LiveSettings& s) {
  check_settings(s);
  const LiveSettings& old = m->settings;
  // "file" keeps the model's own constants: a new material would show in the settings but not in the body.
  const bool own = calibrate::model_kind_of_method(s.model.method) == calibrate::ModelKind::kFile;
  const bool new_law =
      s.model.spring_exponent != old.model.spring_exponent || s.model.volume_exponent != old.model.volume_exponent;
  if (own && (s.material != m->model.material || s.model.density != m->model.density || new_law ||
              !same_surface(s.model.surface, old.model.surface)))
    throw InvalidArgument(
        "this model's constants are its own (method '" + m->model.method +
        "', not one hooke calibrates): a new E, nu, density, term law or surface option needs a method");
  const bool recalibrate = !own && (s.model.method != old.model.method || s.material != old.material ||
                                    s.model.density != old.model.density || s.model.regions != old.model.regions ||
                                    new_law || !same_surface(s.model.surface, old.model.surface));
  // Build everything new first (strong guarantee), then swap.
  std::optional<calibrate::CalibratedModel> model;
  calibrate::BuiltModel built = m->built;
  if (recalibrate) {
    model = calibrate_for(m->model.mesh, s);
    built = calibrate::build_model(*model);
  }
  const VecX x = m->sim->positions(), v = m->sim->velocities();
  const double t = m->sim->time();
  Impl next;
  next.settings = s;
  next.model = model ? std::move(*model) : m->model;
  next.built = std::move(built);
  next.probe = m->probe;
  next.grab_positions = m->grab_positions;
  next.offset = m->offset;
  next.force = m->force;
  next.tool = m->tool;
  next.tool_friction = m->tool_friction;
  next.tool_state = m->tool_state;
  next.model_version = m->model_version + (recalibrate ? 1 : 0);
  next.background_local_model = m->background_local_model;
  next.rebuild(x, v, t);
  *m = std::move(next);
}

const LiveSettings& LiveSimulation::settings() const { return m->settings; }

solve::StepReport LiveSimulation::step() {
  solve::StepReport r = m->sim->step(m->settings.dynamics.dt);
  if (!m->sim->positions().allFinite() || !m->sim->velocities().allFinite())
    throw SolverFailure("the step at t = " + std::to_string(m->sim->time()) +
                        " s produced non-finite positions: use a smaller dt or an implicit integrator");
  if (!std::isfinite(m->sim->potential_energy()))
    throw SolverFailure("the step at t = " + std::to_string(m->sim->time()) +
                        " s inverted an element: use a smaller dt or an implicit integrator");
  const int d = m->dim();
  m->force = r.probe_force.size() == d ? VecX(r.probe_force) : VecX::Zero(d);
  ++m->steps;
  if (m->tool) m->report_tool();
  if (m->settings.haptic_stiffness == HapticStiffness::kSecant && !m->probe.nodes.empty()) m->update_secant();
  return r;
}

HapticModel LiveSimulation::haptic_model() {
  const int d = m->dim();
  HapticModel h;
  h.version = m->steps;
  h.time = m->sim->time();
  h.grabbed = !m->probe.nodes.empty();
  h.offset = m->offset;
  h.force = m->force;
  if (!h.grabbed && m->tool) {
    h.tool = true;
    if (m->settings.haptic_stiffness != HapticStiffness::kNone) h.contact = m->local_contact();
    h.tool_origin = m->tool_origin;
    h.offset = m->tool->pose().position - m->tool_origin.position;
    h.force = m->tool_state->force;
  }
  if (!h.grabbed || m->settings.haptic_stiffness == HapticStiffness::kNone) {
    h.stiffness = MatX::Zero(d, d);
    return h;
  }
  if (!m->local_model_ready()) {  // being made in the background: the force is held until it is there
    h.stiffness = MatX::Zero(d, d);
    return h;
  }
  if (m->settings.haptic_stiffness == HapticStiffness::kSecant) {
    if (m->secant.rows() != d) m->secant = m->contact_stiffness;  // at the grab, before a step has given a pair
    h.stiffness = m->secant;
    h.curvature = m->curvature;
    return h;
  }
  h.stiffness = m->contact_stiffness;
  h.curvature = m->curvature;
  if (h.curvature.rows() == d && h.offset.squaredNorm() > 0.0)  // the tangent at the offset
    h.stiffness = Impl::positive_part(h.stiffness + curvature_along(h.curvature, h.offset));
  return h;
}

void LiveSimulation::reset() { m->reset_state(); }

void LiveSimulation::set_local_model_in_background(bool background) { m->background_local_model = background; }

void LiveSimulation::grab(const std::vector<int>& nodes) {
  const int d = m->dim(), n = m->model.mesh.node_count();
  if (nodes.empty()) throw InvalidArgument("grab needs at least one node");
  for (const int i : nodes)
    if (i < 0 || i >= n)
      throw InvalidArgument("node " + std::to_string(i) + " is not a node of the model (it has " + std::to_string(n) +
                            ")");
  m->probe.nodes = nodes;
  m->forget_local_model();
  m->probe.drive_position = true;
  m->offset.setZero(d);
  m->probe.offset = m->offset;
  m->probe.force = VecX::Zero(d);
  m->grab_positions.resize(d * static_cast<Eigen::Index>(nodes.size()));
  for (size_t k = 0; k < nodes.size(); ++k)
    m->grab_positions.segment(d * static_cast<Eigen::Index>(k), d) = m->sim->positions().segment(d * nodes[k], d);
  m->sim->set_probe(m->probe);
  m->update_interaction();
}

void LiveSimulation::drag(const VecX& offset) {
  if (m->probe.nodes.empty()) return;
  if (offset.size() != m->dim() || !offset.allFinite())
    throw InvalidArgument("a drag needs " + std::to_string(m->dim()) + " finite components");
  m->offset = offset;
  m->probe.offset = offset;
  m->sim->set_probe(m->probe);
  m->update_interaction();
}

void LiveSimulation::release() {
  m->probe = solve::Probe{};
  m->forget_local_model();
  m->grab_positions.resize(0);
  m->offset.setZero(m->dim());
  m->force.setZero(m->dim());
  m->sim->set_probe(m->probe);
  m->interaction.reset();
  m->sim->problem().interaction.reset();
}

void LiveSimulation::set_tool(const std::string& shape, const contact::Pose& pose, double friction) {
  if (m->dim() != 3) throw InvalidArgument("a tool presses 3D bodies only");
  if (!(friction >= 0.0 && std::isfinite(friction)))
    throw InvalidArgument("the friction coefficient must be a finite number >= 0, not " + std::to_string(friction));
  auto tool = std::make_shared<contact::RigidTool>(contact::parse_tool(shape));
  tool->set_pose(pose);
  m->tool = std::move(tool);
  m->tool_origin = pose;
  m->tool_friction = friction;
  m->tool_state.reset();                                         // rebuild makes its contact block
  const VecX x = m->sim->positions(), v = m->sim->velocities();  // copies: rebuild replaces the simulator
  m->rebuild(x, v, m->sim->time());
}

void LiveSimulation::move_tool(const contact::Pose& pose) {
  if (m->tool) m->place_tool(pose);
}

void LiveSimulation::drive_tool(const VecX& offset) {
  if (!m->tool) return;
  if (offset.size() != 3 || !offset.allFinite()) throw InvalidArgument("a tool's offset needs 3 finite components");
  m->place_tool({m->tool_origin.position + offset, m->tool_origin.rotation});
}

double local_contact_reach(const contact::RigidTool& tool, double diagonal, double activation) {
  const bool round = tool.shape() == contact::ToolShape::kSphere || tool.shape() == contact::ToolShape::kCapsule;
  return std::max(round ? tool.radius() : 0.02 * diagonal, activation);
}

void LiveSimulation::remove_tool() {
  if (!m->tool) return;
  m->tool.reset();
  m->contact.reset();
  m->tool_state.reset();
  const VecX x = m->sim->positions(), v = m->sim->velocities();  // copies: rebuild replaces the simulator
  m->rebuild(x, v, m->sim->time());
}

const std::optional<LiveTool>& LiveSimulation::tool() const { return m->tool_state; }

const std::vector<int>& LiveSimulation::grabbed() const { return m->probe.nodes; }
const VecX& LiveSimulation::grab_positions() const { return m->grab_positions; }
const VecX& LiveSimulation::probe_offset() const { return m->offset; }
const VecX& LiveSimulation::probe_force() const { return m->force; }
double LiveSimulation::time() const { return m->sim->time(); }
const VecX& LiveSimulation::positions() const { return m->sim->positions(); }
const VecX& LiveSimulation::velocities() const { return m->sim->velocities(); }
const VecX& LiveSimulation::rest_positions() const { return m->built.model->rest_positions(); }
const calibrate::CalibratedModel& LiveSimulation::model() const { return m->model; }
long LiveSimulation::model_version() const { return m->model_version; }
const surface::VolumePenaltyBlock* LiveSimulation::volume_penalty() const { return m->built.volume_penalty; }
calibrate::BuiltModel LiveSimulation::built_model() const { return m->built; }
const std::optional<model::Interaction>& LiveSimulation::interaction() const { return m->interaction; }
const std::vector<int>& LiveSimulation::clamped_nodes() const { return m->clamped; }
double LiveSimulation::kinetic_energy() const { return m->sim->kinetic_energy(); }
double LiveSimulation::stable_time_step() const { return m->sim->stable_time_step(); }

ProbeEquilibrium probe_equilibrium(const calibrate::CalibratedModel& cm, const std::vector<int>& clamped,
                                   const std::vector<int>& grabbed, const VecX& targets, bool gravity) {
  const int d = cm.mesh.dim(), n = cm.mesh.node_count();
  if (targets.size() != d * static_cast<Eigen::Index>(grabbed.size()) || !targets.allFinite())
    throw InvalidArgument("probe_equilibrium needs " + std::to_string(d) + " finite coordinates per grabbed node");
  for (const std::vector<int>* list : {&clamped, &grabbed})
    for (const int i : *list)
      if (i < 0 || i >= n) throw InvalidArgument("node " + std::to_string(i) + " is not a node of the model");
  const calibrate::BuiltModel built = calibrate::build_model(cm);
  model::Problem problem = model::make_problem(built.model);
  model::fix_nodes(problem, clamped);
  model::fix_nodes(problem, grabbed);
  problem.prescribed_positions = built.model->rest_positions();
  for (size_t k = 0; k < grabbed.size(); ++k)
    problem.prescribed_positions.segment(d * grabbed[k], d) = targets.segment(d * static_cast<Eigen::Index>(k), d);
  problem.external_force = VecX::Zero(built.model->dof_count());
  if (gravity)
    for (int i = 0; i < n; ++i) problem.external_force(d * i + d - 1) = -9.81 * cm.masses(d * i + d - 1);
  model::zero_fixed_forces(problem);
  // The prescribed displacement is applied at once; the linear solution is a start close enough that Newton does
  // not begin from a state with the grabbed nodes torn out of their elements.
  solve::StaticOptions options;
  const solve::StaticResult linear = solve::linear_static(problem);
  if (linear.report.status == solve::SolveStatus::kConverged) options.start = linear.positions;
  const solve::StaticResult r = solve::static_equilibrium(problem, options);
  if (r.report.status != solve::SolveStatus::kConverged)
    throw SolverFailure("the static equilibrium under the probe did not converge: " + r.report.message);
  return ProbeEquilibrium{r.positions, holding_force(problem, r.positions, grabbed), r.report.message};
}

ProbeEquilibrium fem_probe_equilibrium(const calibrate::CalibratedModel& cm, material::Law law,
                                       const std::vector<int>& clamped, const std::vector<int>& grabbed,
                                       const VecX& targets, bool gravity) {
  if (cm.mesh.kind == mesh::ElementKind::kSurfaceTriangle)
    throw InvalidArgument("there is no FEM reference for a surface mesh: it needs tets (or a planar mesh)");
  material::Material mat = cm.material;
  mat.law = law;
  calibrate::ModelOptions o;
  o.method = calibrate::model_kind_name(calibrate::ModelKind::kFem);
  o.density = cm.density;
  o.regions = cm.regions;  // the same tissues
  const calibrate::CalibratedModel fem = calibrate::calibrate_model(cm.mesh, mat, o);
  return probe_equilibrium(fem, clamped, grabbed, targets, gravity);
}

}  // namespace hooke::interactive
