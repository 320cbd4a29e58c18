#pragma once
/// A simulation a user drives while it runs (the viewer's physics, and any haptic loop): a model from the one model
/// factory or a model file, the bottom clamped (spring and FEM models) or held by its anchors (surface model), a probe
/// that grabs nodes and drives them like a stiff haptic device, and settings (material, method, integrator, dt,
/// damping, gravity) that can change between steps without losing the current deformation.
///
/// Not thread-safe: one thread owns it (interactive::PhysicsLoop runs it in its own thread).
#include <hooke/calibrate/calibrated_model.hpp>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/contact/contact_block.hpp>
#include <hooke/interactive/haptic_model.hpp>
#include <hooke/solve/contact_stiffness.hpp>
#include <hooke/solve/dynamics_setup.hpp>
#include <hooke/solve/simulator.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hooke::interactive {

/// What a user can change while the simulation runs.
struct LiveSettings {
  /// How the model is made: the model factory's method (calibrate::model_method_names(), or "file": keep the
  /// model the simulation was made from), density (kg/m^3, > 0) and surface-model options
  calibrate::ModelOptions model;
  material::Material material;  ///< E (Pa), nu, thickness (2D); the law matters for "fem" only
  /// the integrator and its options (solve::SimulatorOptions' defaults: quasi-newton, which runs every model)
  solve::SimulatorOptions simulator;
  solve::DynamicsSetup dynamics;  ///< dt (1 kHz by default, a haptic loop's rate), gravity, damping, Eq. 4's radius
  /// the haptic local model's stiffness (HapticModel::stiffness)
  HapticStiffness haptic_stiffness = HapticStiffness::kSecant;
  /// its condensation region (HapticStiffness::kCondensed; solve::ContactStiffnessOptions)
  solve::ContactStiffnessOptions haptic_region;
  /// the local model carries the condensed energy's third derivative at the grab (HapticModel::curvature,
  /// solve::contact_curvature), so it follows the body's stiffening as the probe moves (docs/simulation.md:
  /// the 11 425-node bench drag at a 0.5 s deformation step renders within 0.95 % of the full-rate force, 12 %
  /// linear); used with kCondensed and kSecant, default on
  bool haptic_curvature = true;
};

/// A rigid tool pressing the live body (docs/contact.md) after the last step.
struct LiveTool {
  contact::RigidTool tool;        ///< shape and pose
  Vec3 force = Vec3::Zero();      ///< the force the body exerts on it, N
  int active = 0;                 ///< boundary nodes within the contact distance
  double smallest_gap = 0.0;      ///< of a boundary node to the tool, m (> 0: none inside)
  double contact_distance = 0.0;  ///< the barrier's activation distance, m
  double friction = 0.0;          ///< Coulomb coefficient
  int pushed_nodes = 0;           ///< nodes put back outside it when it moved faster than their gap
};

/// The most surface nodes a tool's local contact model holds (the nearest the tool).
inline constexpr int kLocalContactNodes = 64;
/// How far from a tool a surface node is taken into its local contact model, m: the radius of a sphere or a capsule,
/// 2 % of the body's bounding-box diagonal `diagonal` (m) for a plane or a mesh; at least the activation distance.
double local_contact_reach(const contact::RigidTool& tool, double diagonal, double activation);

/// A static equilibrium under the probe's current displacement (what the viewer's FEM ghost shows).
struct ProbeEquilibrium {
  VecX positions;       ///< flat, m, in the model's node order
  VecX holding_force;   ///< force the body exerts on the grabbed nodes, N (dim; zero without a probe)
  std::string message;  ///< the static solver's outcome
};

/// The LiveSettings::method that runs `model` as it is and, when E, nu or the density change, remakes it as it was
/// made: "auto" for a model "auto" chose, its own method when the model factory knows it, else "file" (constants
/// hooke cannot remake, such as a hand-tuned model file: a change of material is then refused).
std::string live_method_for(const calibrate::CalibratedModel& model);

class LiveSimulation {
 public:
  /// Calibrates settings.model.method on `mesh` (validated, m) for settings.material.
  /// @throws what calibrate::calibrate_model throws, InvalidArgument for settings out of range
  LiveSimulation(const mesh::Mesh& mesh, const LiveSettings& settings);
  /// Runs `model` (a model file's contents, or a calibration): as it is when settings.model.method is "file", or names
  /// model.method with model.material and model.density; otherwise recalibrates on model.mesh.
  /// @throws InvalidArgument when the model is invalid or the settings out of range
  LiveSimulation(calibrate::CalibratedModel model, const LiveSettings& settings);
  ~LiveSimulation();
  LiveSimulation(LiveSimulation&&) noexcept;
  LiveSimulation& operator=(LiveSimulation&&) noexcept;

  /// Applies new settings: a new method, material, density or surface option re-calibrates the model; a new
  /// integrator, damping or gravity rebuilds the integrator. The current positions and velocities are kept (the
  /// deformation is not lost) and the probe keeps its nodes and target. Strong guarantee: when calibration fails
  /// (e.g. a method that does not apply to the mesh) nothing changes.
  /// @throws what calibrate::calibrate_model throws, InvalidArgument for settings out of range
  void apply(const LiveSettings& settings);
  const LiveSettings& settings() const;

  /// Advances one step of settings().dt.
  /// @throws SolverFailure when the step inverts an element or produces non-finite positions (the state is then
  ///   unusable: call reset)
  solve::StepReport step();
  /// Back to rest, at rest, time 0, probe released.
  void reset();

  /// Grabs `nodes` (model numbering, in range, non-empty) at their current positions; the probe then drives them
  /// to their grab positions plus the offset given to drag (a stiff haptic device). The surface model's Eq. 4
  /// weights follow the probe.
  /// @throws InvalidArgument for an empty list or a node out of range
  void grab(const std::vector<int>& nodes);
  /// Sets the probe's displacement from the grab positions, m (size dim; finite). No effect without a grab.
  void drag(const VecX& offset);
  /// Lets go of the grabbed nodes.
  void release();

  /// Puts a rigid tool ("sphere:R", "capsule:R,L", m: contact::parse_tool) at `pose` against the body's boundary
  /// (contact::boundary_contact: the barrier's activation distance 1 % of the mean boundary edge, kappa from the
  /// model's E), with Coulomb friction `friction` (creep velocity contact::default_creep_velocity). Replaces
  /// the tool there was; kept across apply() (its stiffness follows a new E) and reset(). Nodes inside it are put
  /// back outside. Works beside a grab.
  /// @throws InvalidArgument for a malformed shape, a 2D body, a negative or non-finite friction
  void set_tool(const std::string& shape, const contact::Pose& pose, double friction = 0.0);
  /// Moves the tool (before the next step; nodes it passed are put back outside it). No effect without a tool.
  /// @throws InvalidArgument for a non-finite pose or a matrix that is not a rotation
  void move_tool(const contact::Pose& pose);
  /// Moves the tool to where set_tool put it plus `offset` (m, 3 components; its orientation kept): how a haptic
  /// device drives a tool. No effect without a tool.
  /// @throws InvalidArgument for an offset that is not 3 finite numbers
  void drive_tool(const VecX& offset);
  /// Takes the tool away.
  void remove_tool();
  /// The tool and its contact after the last step (empty without a tool).
  const std::optional<LiveTool>& tool() const;
  const std::vector<int>& grabbed() const;  ///< grabbed nodes, model numbering (empty when released)
  /// Where the grabbed nodes were grabbed, flat, m (dim per grabbed node).
  const VecX& grab_positions() const;
  const VecX& probe_offset() const;  ///< m (dim; zero without a grab)
  /// The force the body exerts on the probe after the last step, N (dim; zero without a grab): minus the force
  /// that holds the grabbed nodes where the probe puts them (solve::StepReport::probe_force).
  const VecX& probe_force() const;
  /// The probe's local model after the last step, for a haptic loop (interactive::HapticModel): the probe force,
  /// the offset it was taken at and the local stiffness of LiveSettings::haptic_stiffness (condensed: computed at
  /// the first call after a grab or a new model; secant: updated by every step).
  /// With a tool and no grab, the tool's local contact model instead (HapticModel::contact): the boundary nodes
  /// within local_contact_reach of the tool (at most kLocalContactNodes, the nearest), their compliance (the
  /// body's rest stiffness factorised at the first call after a new model) and the barrier.
  /// @throws SolverFailure when the condensation fails (a body not held)
  HapticModel haptic_model();
  /// Whether the grab's condensed stiffness and curvature (above) are made in a thread of their own (true: the
  /// steps go on meanwhile and the local model holds the force, stiffness zero, until they are there; a real-time
  /// PhysicsLoop sets it: on the 11 425-node cylinder they stalled the first step after a grab by 0.9 s) or in the
  /// calling thread at the first call (false, the default: scripted runs are the same every time).
  void set_local_model_in_background(bool background);

  double time() const;                              ///< simulated time, s
  const VecX& positions() const;                    ///< flat, m, model numbering
  const VecX& velocities() const;                   ///< flat, m/s
  const VecX& rest_positions() const;               ///< flat, m
  const calibrate::CalibratedModel& model() const;  ///< the model being simulated
  /// Increases each time apply() recalibrates the model (0 for the first): what a front end caching data of the
  /// model (its springs, say) compares.
  long model_version() const;
  /// The surface model's volume penalty (null for other models): Eq. 4 weights for drawing.
  const surface::VolumePenaltyBlock* volume_penalty() const;
  /// The term blocks being simulated, shared: they stay valid after apply() replaces them, and being immutable
  /// they may be evaluated from another thread while the simulation steps (the viewer's Eq. 4 weights).
  calibrate::BuiltModel built_model() const;
  /// The surface model's current interaction (the probe's point and direction), if any.
  const std::optional<model::Interaction>& interaction() const;
  /// Nodes clamped at the bottom (empty for the surface model), model numbering.
  const std::vector<int>& clamped_nodes() const;
  double kinetic_energy() const;    ///< J
  double stable_time_step() const;  ///< explicit stability limit of the current model, s

 private:
  struct Impl;
  std::unique_ptr<Impl> m;
};

/// The static equilibrium of `model` with the `clamped` nodes at rest, the `grabbed` nodes held at `targets` (flat,
/// m, dim per grabbed node) and gravity when asked: positions and the holding force (what a probe holding them
/// feels: minus the force that keeps them there), by solve::static_equilibrium (Newton with load stepping).
/// @throws InvalidArgument for nodes out of range or targets of the wrong size; SolverFailure when the solve does not
///   converge to a stable equilibrium
ProbeEquilibrium probe_equilibrium(const calibrate::CalibratedModel& model, const std::vector<int>& clamped,
                                   const std::vector<int>& grabbed, const VecX& targets, bool gravity);

/// The same under the FEM of model.mesh with model.material and `law` (the viewer's ghost): the reference the springs
/// are compared with. Needs a volume (tets) or planar (triangles, quads) mesh.
/// @throws InvalidArgument for a surface mesh; what probe_equilibrium throws
ProbeEquilibrium fem_probe_equilibrium(const calibrate::CalibratedModel& model, material::Law law,
                                       const std::vector<int>& clamped, const std::vector<int>& grabbed,
                                       const VecX& targets, bool gravity);

}  // namespace hooke::interactive
