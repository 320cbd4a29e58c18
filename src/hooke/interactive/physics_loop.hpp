#pragma once
/// A live simulation in its own thread at a fixed rate (a haptic loop: one step of dt seconds every dt seconds of
/// wall time, 1 kHz by default), apart from whoever draws it. The drawing side posts commands (grab, drag, new
/// settings) and copies the latest consistent state; the loop measures what it achieves (steps per second of wall
/// time, ms per step) and says when it falls behind instead of silently slowing down.
///
/// Thread-safe: every member may be called from any thread (and from a posted command or a with() command); no
/// callback of the front end runs in the physics thread with a lock held.
#include <atomic>
#include <condition_variable>
#include <deque>
#include <functional>
#include <hooke/core/settings.hpp>
#include <hooke/interactive/haptic_model.hpp>
#include <hooke/interactive/live_simulation.hpp>
#include <hooke/interactive/script.hpp>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace hooke::interactive {

/// What the physics thread achieved.
struct PhysicsStats {
  double target_rate = 0.0;  ///< steps per second of wall time wanted: 1 / dt, Hz
  /// steps completed per second of wall time over the last second (or since the start or a pause), Hz: the steps
  /// over the wall time from the first one's start to the last one's end (at least a period per step when paced)
  double achieved_rate = 0.0;
  double step_ms_median = 0.0;  ///< median wall time of a step over the last 1 000 steps, ms
  double step_ms_p99 = 0.0;     ///< 99th percentile of the same, ms
  long steps = 0;               ///< steps since the start
  long overruns = 0;            ///< steps that took longer than their period
  bool behind = false;          ///< the achieved rate is below the target (by more than 1 %)
  bool paused = false;
  double sim_time = 0.0;   ///< s
  double wall_time = 0.0;  ///< s since start() (not counting pauses)
  long iterations = 0;     ///< Newton / local-global iterations since the start
  int not_converged = 0;   ///< steps that ended above the Newton tolerance
  std::string error;       ///< the last failure (a step that inverted an element, a calibration that failed)
};

/// Simulated time over wall time since the loop started (pauses excluded): the fraction of real time the whole run
/// kept, beside achieved_rate's last second; 0 before the first step.
double real_time_fraction(const PhysicsStats& s);

/// The fraction of all steps so far that ended above the solver's tolerance, in [0, 1]; 0 before the first step.
double fraction_above_tolerance(const PhysicsStats& s);

/// The latest consistent state, as the drawing side sees it.
struct Snapshot {
  long version = 0;          ///< increases with every published state
  VecX positions;            ///< flat, m
  VecX probe_force;          ///< N (dim)
  std::vector<int> grabbed;  ///< model numbering
  VecX grab_positions;       ///< flat, m
  VecX probe_offset;         ///< m (dim)
  std::optional<model::Interaction> interaction;
  LiveSettings settings;
  long model_version = 0;        ///< increases when the model is recalibrated or replaced
  std::optional<LiveTool> tool;  ///< the tool pressing the body and its force (empty: none)
  PhysicsStats stats;
};

class PhysicsLoop {
 public:
  /// Takes over `simulation`; the thread starts with start(). realtime = false steps as fast as it can (for
  /// scripted runs where wall time does not matter). `threads`: OpenMP threads of the physics (>= 1; default 1:
  /// measured on two cores, one thread steps the 1 089-node cylinder with local/global in 0.41 ms where two
  /// take 0.41 ms when they may spin and 0.85 ms when they must sleep, and the drawing needs the other core).
  explicit PhysicsLoop(LiveSimulation simulation, bool realtime = true, int threads = 1);
  ~PhysicsLoop();  ///< stops the thread
  PhysicsLoop(const PhysicsLoop&) = delete;
  PhysicsLoop& operator=(const PhysicsLoop&) = delete;

  void start();
  void stop();  ///< joins the thread; idempotent

  /// Runs `command` in the physics thread before its next step. An exception it throws is reported in
  /// PhysicsStats::error (the simulation is left as the command left it). The command may call any member of the
  /// loop (post, with, snapshot, stats, ...).
  void post(std::function<void(LiveSimulation&)> command);
  /// Runs `command` on the simulation now, from the calling thread, while the physics thread waits between two
  /// steps (for reads that need the whole simulation, e.g. the model for the FEM ghost). The command may call the
  /// loop's other members, and with() again (it then runs at once: the simulation is already held).
  void with(const std::function<void(const LiveSimulation&)>& command);

  /// Copies the latest state into `out` when it is newer than out.version; returns whether it did.
  bool snapshot(Snapshot& out) const;
  PhysicsStats stats() const;

  void set_paused(bool paused);
  bool paused() const;

  /// Multirate haptics (HapticLoop): from now on the physics publishes the probe's (or the tool's) local model after
  /// every step (LiveSimulation::haptic_model; the first one after a grab condenses the stiffness, the first with a
  /// tool factorises the body's rest stiffness: a longer step).
  void enable_haptics();
  /// The probe's offset for the next step, m (dim): a haptic device's position. Replaces one not yet taken (no
  /// queue: only the newest matters). Without a grab it moves the tool from where it was put
  /// (LiveSimulation::drive_tool); ignored with neither.
  void set_device_offset(const VecX& offset);
  /// The local model after the last step (before the first: the one the thread published when it started, that of
  /// the state it started from; version 0 without enable_haptics()). Takes only a
  /// lock of its own, never held for longer than a copy of dim + dim^2 numbers.
  HapticModel haptic_model() const;

  /// Replays `script` (times in simulated time): physics commands run in the thread; at a drawing command
  /// (is_drawing) the physics publishes the state of that time and, when `front_end_draws`, waits until the front
  /// end has taken the command with drawing_commands() and called drawing_done() (so a screenshot shows the state
  /// at its time); otherwise drawing commands are skipped. Call before start().
  /// @throws InvalidArgument when the thread is running
  void set_script(std::vector<ScriptCommand> script, bool front_end_draws = true);
  /// The drawing commands whose time has come (in script order; empty when none), and in `out` the state published
  /// at their time (the same as snapshot() gives, taken under the same lock, so never an older one).
  std::vector<ScriptCommand> drawing_commands(Snapshot& out);
  /// The front end has carried out the commands drawing_commands() gave: the physics goes on.
  void drawing_done();
  bool script_finished() const;  ///< every command has been carried out

 private:
  void run();                   // the thread: run_steps, with any exception reported in PhysicsStats::error
  void run_steps();             // the loop
  void take_inputs();           // the scripted drag's ramp and the device's newest offset, into the simulation
  void publish_haptic_model();  // the probe's local model for the haptic loop, after enable_haptics()
  void stage();                 // copies the simulation's state into m_staging (physics thread, m_sim_mutex held)
  void publish();               // m_staging becomes the latest snapshot (takes m_mutex)
  void run_commands(std::deque<std::function<void(LiveSimulation&)>>& commands);
  bool run_script_commands();                            // true when a drawing command waits for the front end
  std::unique_lock<std::mutex> lock_simulation() const;  // m_sim_mutex, let in by the physics thread

  // Two locks, always taken in this order when both are held: m_sim_mutex (the simulation: held by the physics
  // thread while it steps and by with()), then m_mutex (what the threads exchange: held only to copy or swap).
  LiveSimulation m_sim;       // guarded by m_sim_mutex
  PhysicsStats m_work_stats;  // the physics thread's running stats (m_sim_mutex)
  Snapshot m_staging;         // the next snapshot, filled under m_sim_mutex
  bool m_realtime;
  int m_threads;
  std::thread m_thread;
  mutable std::mutex m_sim_mutex;
  mutable std::atomic<int> m_waiters{0};               // threads waiting for m_sim_mutex: the physics lets them in
  mutable std::atomic<std::thread::id> m_sim_owner{};  // the thread holding m_sim_mutex (for with() re-entry)
  mutable std::mutex m_mutex;                          // guards everything below
  std::condition_variable m_wake;
  bool m_stop = false, m_paused = false, m_waiting_for_drawing = false;
  std::deque<std::function<void(LiveSimulation&)>> m_commands;
  Snapshot m_latest;
  std::vector<ScriptCommand> m_pending_drawing;  // drawing commands the front end has not taken yet
  // The script: set before start(), then read by the physics thread only; m_script_next is read by
  // script_finished().
  std::vector<ScriptCommand> m_script;
  std::atomic<size_t> m_script_next{0};
  bool m_front_end_draws = true;
  // Multirate haptics: the device's offset for the next step and the local model after the last, under a lock of
  // their own (the haptic thread must not wait for a snapshot's copy).
  std::atomic<bool> m_haptics{false};
  mutable std::mutex m_haptic_mutex;
  VecX m_device_offset;
  bool m_device_pending = false;
  HapticModel m_haptic;
  // A drag being ramped by the script: from m_drag_from to m_drag_to between m_drag_t0 and m_drag_t1 (sim time).
  VecX m_drag_from, m_drag_to;
  double m_drag_t0 = 0.0, m_drag_t1 = -1.0;
  // A tool move being ramped by the script, likewise.
  Vec3 m_tool_from = Vec3::Zero(), m_tool_to = Vec3::Zero();
  double m_tool_t0 = 0.0, m_tool_t1 = -1.0;
};

/// Carries out one `set` script command on settings (young, poisson, the live model settings: method, density, ...;
/// live_model_settings, haptic-stiffness, haptic-curvature on|off, the dynamics fields: dt, gravity, damping-mass, ...;
/// solve::dynamics_fields, and the integrator's: integrator, qn-iterations, cg-tolerance, ...;
/// solve::simulator_fields).
/// @throws InvalidArgument for a value that does not parse or is out of range
void apply_setting(LiveSettings& settings, const std::string& key, const std::string& value);

/// The model settings the viewer changes while it runs (calibrate::model_settings() rows of settings::kView: method,
/// density, term law, surface options), each a `set` key and a panel control; changing one recalibrates.
const std::vector<settings::Description>& live_model_settings();

/// Writes `stats` plus `extra` (JSON members of numbers) as a JSON object to `path` (atomically).
/// @throws IoError when it cannot be written
void write_stats(const std::string& path, const PhysicsStats& stats,
                 const std::vector<std::pair<std::string, double>>& extra);

}  // namespace hooke::interactive
