#pragma once
/// A live simulation in its own thread at a fixed rate (a haptic loop: one step of dt seconds every dt seconds of
/// wall time, 1 kHz by default), apart from whoever draws it. The drawing side posts commands (grab, drag, new
/// settings) and copies the latest consistent state; the loop measures what it achieves (steps per second of wall
/// time, ms per step) and says when it falls behind instead of silently slowing down.
#include <atomic>
#include <condition_variable>
#include <deque>
#include <functional>
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
  long model_version = 0;  ///< increases when the model is recalibrated or replaced
  PhysicsStats stats;
};

/// A drawing command of a script, handed to the front end when its time comes (is_drawing).
using DrawingHandler = std::function<void(const ScriptCommand&)>;

class PhysicsLoop {
 public:
  /// Takes over `simulation`; the thread starts with start(). realtime = false steps as fast as it can (for
  /// scripted runs where wall time does not matter). `threads`: OpenMP threads of the physics (>= 1; default 1:
  /// measured on the 2-core machine, one thread steps the 1 089-node cylinder with local/global in 0.41 ms where two
  /// take 0.41 ms when they may spin and 0.85 ms when they must sleep, and the drawing needs the other core).
  explicit PhysicsLoop(LiveSimulation simulation, bool realtime = true, int threads = 1);
  ~PhysicsLoop();  ///< stops the thread
  PhysicsLoop(const PhysicsLoop&) = delete;
  PhysicsLoop& operator=(const PhysicsLoop&) = delete;

  void start();
  void stop();  ///< joins the thread; idempotent

  /// Runs `command` in the physics thread before its next step. An exception it throws is reported in
  /// PhysicsStats::error (the simulation is left as the command left it).
  void post(std::function<void(LiveSimulation&)> command);
  /// Runs `command` on the simulation now, from the calling thread, while the physics thread waits (for reads that
  /// need the whole simulation, e.g. the model for the FEM ghost).
  void with(const std::function<void(const LiveSimulation&)>& command);

  /// Copies the latest state into `out` when it is newer than out.version; returns whether it did.
  bool snapshot(Snapshot& out) const;
  PhysicsStats stats() const;

  void set_paused(bool paused);
  bool paused() const;

  /// Replays `script` (times in simulated time): physics commands run in the thread, drawing commands go to
  /// `drawing`, called from the physics thread; the physics then waits until the front end calls
  /// drawing_done() (so a screenshot shows the state at its time). Call before start().
  void set_script(std::vector<ScriptCommand> script, DrawingHandler drawing);
  void drawing_done();
  bool script_finished() const;  ///< every command has been carried out

 private:
  void run();        // the thread: run_steps, with any exception reported in PhysicsStats::error
  void run_steps();  // the loop
  void publish();
  void run_script_commands();

  LiveSimulation m_sim;
  bool m_realtime;
  int m_threads;
  std::thread m_thread;
  mutable std::atomic<int> m_waiters{0};  // other threads waiting for m_mutex: the physics lets them in
  mutable std::mutex m_mutex;             // guards everything below
  std::condition_variable m_wake;
  bool m_stop = false, m_paused = false, m_waiting_for_drawing = false;
  std::deque<std::function<void(LiveSimulation&)>> m_commands;
  Snapshot m_latest;
  PhysicsStats m_stats;
  std::vector<ScriptCommand> m_script;
  size_t m_script_next = 0;
  DrawingHandler m_drawing;
  // A drag being ramped by the script: from m_drag_from to m_drag_to between m_drag_t0 and m_drag_t1 (sim time).
  VecX m_drag_from, m_drag_to;
  double m_drag_t0 = 0.0, m_drag_t1 = -1.0;
};

/// Carries out one `set` script command on settings (young, poisson, density, method, integrator, dt, damping-mass,
/// damping-stiffness, gravity).
/// @throws InvalidArgument for a value that does not parse or is out of range
void apply_setting(LiveSettings& settings, const std::string& key, const std::string& value);

/// Writes `stats` plus `extra` (JSON members of numbers) as a JSON object to `path` (atomically).
/// @throws IoError when it cannot be written
void write_stats(const std::string& path, const PhysicsStats& stats,
                 const std::vector<std::pair<std::string, double>>& extra);

}  // namespace hooke::interactive
