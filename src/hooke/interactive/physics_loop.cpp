#include <omp.h>
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <hooke/calibrate/model_settings.hpp>
#include <hooke/core/atomic_file.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/quantile.hpp>
#include <hooke/interactive/physics_loop.hpp>
#include <hooke/solve/dynamics_setup.hpp>
#include <hooke/solve/simulator_settings.hpp>
#include <nlohmann/json.hpp>

namespace hooke::interactive {
namespace {

using Clock = std::chrono::steady_clock;

// Wall times of the last steps (a ring of 1 000) and when they ended, for the rate and the percentiles.
struct StepClock {
  static constexpr size_t kWindow = 1000;
  std::vector<double> ms = std::vector<double>(kWindow, 0.0);
  std::deque<Clock::time_point> starts;  // starts of the steps that ended within the last second
  Clock::time_point last_end;
  size_t count = 0;

  void add(double step_ms, Clock::time_point start, Clock::time_point end) {
    ms[count % kWindow] = step_ms;
    ++count;
    starts.push_back(start);
    last_end = end;
    while (!starts.empty() && end - starts.front() > std::chrono::seconds(1)) starts.pop_front();
  }
  // Steps completed per second of wall time over the window: the steps over the wall time from the first one's
  // start to the last one's end, that time at least one period per step when paced (a paced loop cannot run ahead
  // of its target, and a step that took less than its period still took a period of wall time).
  double rate(double period, bool paced) const {
    if (starts.empty()) return 0.0;
    const auto n = static_cast<double>(starts.size());
    double span = std::chrono::duration<double>(last_end - starts.front()).count();
    if (paced) span = std::max(span, n * period);
    return span > 0.0 ? n / span : 0.0;
  }
  std::vector<double> window() const {
    return std::vector<double>(ms.begin(), ms.begin() + static_cast<long>(std::min(count, kWindow)));
  }
};

// Records the thread holding the simulation's lock for as long as it lives (declared after the lock, so it ends
// first): with() called by that thread runs at once instead of deadlocking.
struct OwnerMark {
  std::atomic<std::thread::id>& owner;
  explicit OwnerMark(std::atomic<std::thread::id>& o) : owner(o) { owner = std::this_thread::get_id(); }
  ~OwnerMark() { owner = std::thread::id(); }
  OwnerMark(const OwnerMark&) = delete;
  OwnerMark& operator=(const OwnerMark&) = delete;
};

// A step's wall time [t0, t1] into `clock` and the stats: steps, overruns, wall time (s, pauses excluded), the rate
// and whether it is behind, and now and then the percentiles.
void record_step(PhysicsStats& st, StepClock& clock, Clock::time_point t0, Clock::time_point t1, double wall_time,
                 double period, bool paced) {
  const double step_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  clock.add(step_ms, t0, t1);
  ++st.steps;
  if (step_ms > 1e3 * period) ++st.overruns;
  st.wall_time = wall_time;
  // Steps per wall second over the last second (since the last pause while that is shorter); behind whenever
  // that is below the target (1 % for the scheduler's wake-up jitter), paced or not.
  st.achieved_rate = clock.rate(period, paced);
  st.behind = st.achieved_rate < 0.99 / period;
  if (clock.count % 100 == 1 || clock.count < 100) {  // percentiles now and then: sorting 1 000 values costs ~20 us
    const std::vector<double> w = clock.window();
    st.step_ms_median = quantile(w, 0.5);
    st.step_ms_p99 = quantile(w, 0.99);
  }
}

// Sleeps until `next` advanced by one period (s): one step per period of wall time. Behind by more than 50
// periods, the backlog is dropped (the panel says it is behind) rather than run flat out to catch up.
void pace(Clock::time_point& next, double period) {
  next += std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(period));
  if (Clock::now() - next > std::chrono::duration<double>(50 * period)) next = Clock::now();
  std::this_thread::sleep_until(next);
}

}  // namespace

const std::vector<settings::Description>& live_model_settings() {
  static const std::vector<settings::Description> rows =
      settings::describe(calibrate::model_settings(), settings::kView);
  return rows;
}

void apply_setting(LiveSettings& s, const std::string& key, const std::string& value) {
  if (key == "young") {
    s.material.youngs_modulus = solve::setting_number(key, value);
  } else if (key == "poisson") {
    s.material.poisson_ratio = solve::setting_number(key, value);
  } else if (key == "method" && value == calibrate::model_kind_name(calibrate::ModelKind::kFile)) {
    s.model.method = value;  // keep a model file's own constants
  } else if (const std::string name = settings::canonical_name(key);
             std::any_of(live_model_settings().begin(), live_model_settings().end(),
                         [&](const settings::Description& d) { return d.name == name; })) {
    settings::set(calibrate::model_settings(), s.model, name, value);
  } else if (key == "haptic-stiffness") {
    s.haptic_stiffness = haptic_stiffness_from_name(value);
  } else if (key == "haptic-curvature") {
    s.haptic_curvature = solve::setting_flag(key, value);
  } else if (!solve::set_dynamics_field(s.dynamics, key, value) &&
             !solve::set_simulator_field(s.simulator, key, value)) {
    throw InvalidArgument("unknown setting '" + key + "'");
  }
}

PhysicsLoop::PhysicsLoop(LiveSimulation simulation, bool realtime, int threads)
    : m_sim(std::move(simulation)), m_realtime(realtime), m_threads(std::max(threads, 1)) {
  if (realtime) m_sim.set_local_model_in_background(true);  // a grab must not stall the clock
  m_work_stats.target_rate = 1.0 / m_sim.settings().dynamics.dt;
  stage();
  publish();
}

PhysicsLoop::~PhysicsLoop() { stop(); }

void PhysicsLoop::start() {
  if (!m_thread.joinable()) m_thread = std::thread([this] { run(); });
}

void PhysicsLoop::stop() {
  {
    std::lock_guard lock(m_mutex);
    m_stop = true;
    m_waiting_for_drawing = false;
  }
  m_wake.notify_all();
  if (m_thread.joinable() && m_thread.get_id() != std::this_thread::get_id()) m_thread.join();
}

void PhysicsLoop::post(std::function<void(LiveSimulation&)> command) {
  std::lock_guard lock(m_mutex);
  m_commands.push_back(std::move(command));
}

// m_sim_mutex for a thread other than the physics: it announces itself in m_waiters, and the physics thread, which
// takes the lock again right after each step, yields until the waiters are through.
std::unique_lock<std::mutex> PhysicsLoop::lock_simulation() const {
  ++m_waiters;
  std::unique_lock lock(m_sim_mutex);
  --m_waiters;
  return lock;
}

void PhysicsLoop::with(const std::function<void(const LiveSimulation&)>& command) {
  if (m_sim_owner.load() == std::this_thread::get_id()) {  // re-entry (or the physics thread): already held
    command(m_sim);
    return;
  }
  const std::unique_lock lock = lock_simulation();
  const OwnerMark mark(m_sim_owner);
  command(m_sim);
}

bool PhysicsLoop::snapshot(Snapshot& out) const {
  std::lock_guard lock(m_mutex);
  if (out.version == m_latest.version) return false;
  out = m_latest;
  return true;
}

PhysicsStats PhysicsLoop::stats() const {
  std::lock_guard lock(m_mutex);
  return m_latest.stats;
}

void PhysicsLoop::set_paused(bool paused) {
  {
    std::lock_guard lock(m_mutex);
    m_paused = paused;
    m_latest.stats.paused = paused;
  }
  m_wake.notify_all();
}

bool PhysicsLoop::paused() const {
  std::lock_guard lock(m_mutex);
  return m_paused;
}

void PhysicsLoop::enable_haptics() { m_haptics = true; }

void PhysicsLoop::set_device_offset(const VecX& offset) {
  std::lock_guard lock(m_haptic_mutex);
  m_device_offset = offset;
  m_device_pending = true;
}

HapticModel PhysicsLoop::haptic_model() const {
  std::lock_guard lock(m_haptic_mutex);
  return m_haptic;
}

void PhysicsLoop::set_script(std::vector<ScriptCommand> script, bool front_end_draws) {
  if (m_thread.joinable()) throw InvalidArgument("PhysicsLoop::set_script: the physics thread is already running");
  std::lock_guard lock(m_mutex);
  m_script = std::move(script);
  m_script_next = 0;
  m_front_end_draws = front_end_draws;
}

std::vector<ScriptCommand> PhysicsLoop::drawing_commands(Snapshot& out) {
  std::lock_guard lock(m_mutex);
  std::vector<ScriptCommand> commands;
  commands.swap(m_pending_drawing);
  if (out.version != m_latest.version) out = m_latest;
  return commands;
}

void PhysicsLoop::drawing_done() {
  {
    std::lock_guard lock(m_mutex);
    m_waiting_for_drawing = false;
  }
  m_wake.notify_all();
}

bool PhysicsLoop::script_finished() const {
  std::lock_guard lock(m_mutex);
  return m_script_next.load() >= m_script.size() && !m_waiting_for_drawing && m_pending_drawing.empty();
}

// Physics thread, m_sim_mutex held: the state of the simulation into m_staging (no allocation once sizes settle).
void PhysicsLoop::stage() {
  Snapshot& s = m_staging;
  s.positions = m_sim.positions();
  s.probe_force = m_sim.probe_force();
  s.grabbed = m_sim.grabbed();
  s.grab_positions = m_sim.grab_positions();
  s.probe_offset = m_sim.probe_offset();
  s.interaction = m_sim.interaction();
  s.settings = m_sim.settings();
  s.model_version = m_sim.model_version();
  s.tool = m_sim.tool();
  m_work_stats.sim_time = m_sim.time();
  s.stats = m_work_stats;
}

// m_staging becomes the latest snapshot; the old one is m_staging's storage for the next stage().
void PhysicsLoop::publish() {
  std::lock_guard lock(m_mutex);
  m_staging.version = m_latest.version + 1;
  m_staging.stats.paused = m_paused;
  std::swap(m_staging, m_latest);
}

// Physics thread, m_sim_mutex held: the front end's commands, each caught on its own.
void PhysicsLoop::run_commands(std::deque<std::function<void(LiveSimulation&)>>& commands) {
  while (!commands.empty()) {
    auto command = std::move(commands.front());
    commands.pop_front();
    try {
      command(m_sim);
      m_work_stats.target_rate = 1.0 / m_sim.settings().dynamics.dt;
    } catch (const std::exception& e) {
      m_work_stats.error = e.what();
    }
  }
}

// Physics thread, m_sim_mutex held: the script's commands whose time has come. A drawing command is published with
// the state of its time and handed to the front end; true when the physics must then wait for drawing_done().
bool PhysicsLoop::run_script_commands() {
  const int d = m_sim.model().mesh.dim();
  while (m_script_next < m_script.size() &&
         m_script[m_script_next].time <= m_sim.time() + 1e-9 * m_sim.settings().dynamics.dt) {
    const ScriptCommand& c = m_script[m_script_next];
    try {
      switch (c.action) {
        case ScriptAction::kGrab: m_sim.grab(c.nodes); break;
        case ScriptAction::kGrabNearest: {
          const RowMatX x = mesh::positions_as_rows(m_sim.positions(), d);
          Eigen::Index best = 0;
          (x.rowwise() - c.vector.head(d).transpose()).rowwise().squaredNorm().minCoeff(&best);
          m_sim.grab({static_cast<int>(best)});
          break;
        }
        case ScriptAction::kDrag:
          m_drag_from = m_sim.probe_offset();
          m_drag_to = c.vector.head(d);
          m_drag_t0 = m_sim.time();
          m_drag_t1 = m_drag_t0 + c.duration;
          if (c.duration <= 0.0) {
            m_sim.drag(m_drag_to);
            m_drag_t1 = -1.0;
          }
          break;
        case ScriptAction::kRelease:
          m_drag_t1 = -1.0;
          m_sim.release();
          break;
        case ScriptAction::kTool:
          m_tool_t1 = -1.0;
          if (c.key == "none")
            m_sim.remove_tool();
          else
            m_sim.set_tool(c.key, {c.vector, Mat3::Identity()}, c.friction);
          break;
        case ScriptAction::kMoveTool:
          if (!m_sim.tool()) throw InvalidArgument("move-tool needs a tool (the tool command)");
          m_tool_from = m_sim.tool()->tool.pose().position;
          m_tool_to = c.vector;
          m_tool_t0 = m_sim.time();
          m_tool_t1 = m_tool_t0 + c.duration;
          if (c.duration <= 0.0) {
            m_sim.move_tool({m_tool_to, Mat3::Identity()});
            m_tool_t1 = -1.0;
          }
          break;
        case ScriptAction::kSet: {
          LiveSettings s = m_sim.settings();
          apply_setting(s, c.key, c.value);
          m_sim.apply(s);
          m_work_stats.target_rate = 1.0 / s.dynamics.dt;
          break;
        }
        case ScriptAction::kReset:
          m_drag_t1 = m_tool_t1 = -1.0;
          m_sim.reset();
          break;
        case ScriptAction::kPause:
        case ScriptAction::kResume: {
          std::lock_guard lock(m_mutex);
          m_paused = c.action == ScriptAction::kPause;
          break;
        }
        default:  // drawing: the front end takes it with the state of this time
          if (!m_front_end_draws) break;
          stage();
          {
            // The command moves from the script to the front end under one lock: script_finished() never sees it
            // in neither place (the front end would stop before a last `quit` or `screenshot`).
            std::lock_guard lock(m_mutex);
            ++m_script_next;
            m_pending_drawing.push_back(c);
            m_waiting_for_drawing = true;
          }
          publish();
          return true;
      }
    } catch (const std::exception& e) {
      m_work_stats.error = "script line " + std::to_string(c.line) + ": " + e.what();
    }
    ++m_script_next;
  }
  return false;
}

void PhysicsLoop::run() {
  try {
    run_steps();
  } catch (const std::exception& e) {  // never std::terminate: the front end reads the error and goes on drawing
    std::lock_guard lock(m_mutex);
    m_latest.stats.error = std::string("the physics thread stopped: ") + e.what();
    ++m_latest.version;
  }
}

void PhysicsLoop::publish_haptic_model() {
  if (!m_haptics) return;
  try {
    HapticModel model = m_sim.haptic_model();
    std::lock_guard lock(m_haptic_mutex);
    std::swap(m_haptic, model);
  } catch (const std::exception& e) {
    m_work_stats.error = std::string("haptic model: ") + e.what();
  }
}

void PhysicsLoop::take_inputs() {
  // A scripted drag ramps linearly in simulated time.
  if (m_drag_t1 >= 0.0 && !m_sim.grabbed().empty()) {
    const double f =
        m_drag_t1 > m_drag_t0 ? std::clamp((m_sim.time() - m_drag_t0) / (m_drag_t1 - m_drag_t0), 0.0, 1.0) : 1.0;
    m_sim.drag(m_drag_from + f * (m_drag_to - m_drag_from));
    if (f >= 1.0) m_drag_t1 = -1.0;
  }
  if (m_tool_t1 >= 0.0 && m_sim.tool()) {  // and a scripted tool move
    const double f =
        m_tool_t1 > m_tool_t0 ? std::clamp((m_sim.time() - m_tool_t0) / (m_tool_t1 - m_tool_t0), 0.0, 1.0) : 1.0;
    m_sim.move_tool({m_tool_from + f * (m_tool_to - m_tool_from), m_sim.tool()->tool.pose().rotation});
    if (f >= 1.0) m_tool_t1 = -1.0;
  }
  {  // a haptic device's offset, the newest
    std::unique_lock lock(m_haptic_mutex);
    if (m_device_pending) {
      m_device_pending = false;
      const VecX offset = m_device_offset;
      lock.unlock();
      try {  // the device drives the grab, or else the tool
        if (m_sim.grabbed().empty() && m_sim.tool())
          m_sim.drive_tool(offset);
        else
          m_sim.drag(offset);
      } catch (const std::exception& e) {
        m_work_stats.error = std::string("device offset: ") + e.what();
      }
    }
  }
}

void PhysicsLoop::run_steps() {
  omp_set_num_threads(m_threads);  // this thread's parallel regions
  publish_haptic_model();          // the grab's, before the first step ends
  StepClock clock;
  const Clock::time_point start = Clock::now();
  Clock::time_point next = start;
  double paused_seconds = 0.0;
  std::deque<std::function<void(LiveSimulation&)>> commands;
  const auto wait = [&](auto&& until) {  // a wait that is not the physics' time
    const Clock::time_point t0 = Clock::now();
    {
      std::unique_lock lock(m_mutex);
      until(lock);
    }
    paused_seconds += std::chrono::duration<double>(Clock::now() - t0).count();
    clock.starts.clear();
    next = Clock::now();
  };
  // One step (m_sim_mutex held), its wall time and the rate in the stats.
  const auto step_once = [&] {
    take_inputs();
    PhysicsStats& st = m_work_stats;
    const Clock::time_point t0 = Clock::now();
    try {
      const solve::StepReport r = m_sim.step();
      st.iterations += r.iterations;
      st.not_converged += r.converged ? 0 : 1;
    } catch (const std::exception& e) {
      st.error = std::string(e.what()) + " (the simulation was reset)";
      m_sim.reset();
    }
    publish_haptic_model();
    const Clock::time_point t1 = Clock::now();
    record_step(st, clock, t0, t1, std::chrono::duration<double>(t1 - start).count() - paused_seconds,
                m_sim.settings().dynamics.dt, m_realtime);
  };
  enum class Outcome { kStepped, kDrawing, kPaused };
  for (;;) {
    {
      std::lock_guard lock(m_mutex);
      if (m_stop) return;
      commands.swap(m_commands);
    }
    Outcome outcome = Outcome::kStepped;
    double period = 0.0;
    {
      const std::lock_guard sim(m_sim_mutex);
      const OwnerMark mark(m_sim_owner);
      // Commands from the front end, then the script's.
      run_commands(commands);
      if (run_script_commands()) {
        outcome = Outcome::kDrawing;  // published: the front end draws this state
      } else if (paused()) {
        outcome = Outcome::kPaused;
        stage();
      } else {
        step_once();
        stage();
      }
      period = m_sim.settings().dynamics.dt;
    }
    if (outcome == Outcome::kDrawing) {
      wait([this](std::unique_lock<std::mutex>& lock) {
        m_wake.wait(lock, [this] { return m_stop || !m_waiting_for_drawing; });
      });
      continue;
    }
    publish();
    if (outcome == Outcome::kPaused) {
      wait([this](std::unique_lock<std::mutex>& lock) { m_wake.wait_for(lock, std::chrono::milliseconds(5)); });
      continue;
    }
    if (m_realtime) pace(next, period);
    while (m_waiters.load() > 0) std::this_thread::yield();  // let with() in before the next step takes the lock
  }
}

double real_time_fraction(const PhysicsStats& s) { return s.wall_time > 0.0 ? s.sim_time / s.wall_time : 0.0; }

double fraction_above_tolerance(const PhysicsStats& s) {
  return s.steps > 0 ? static_cast<double>(s.not_converged) / static_cast<double>(s.steps) : 0.0;
}

void write_stats(const std::string& path, const PhysicsStats& s,
                 const std::vector<std::pair<std::string, double>>& extra) {
  nlohmann::ordered_json j;
  j["target_rate_hz"] = s.target_rate;
  j["achieved_rate_hz"] = s.achieved_rate;
  j["steps_per_wall_second"] = s.wall_time > 0.0 ? static_cast<double>(s.steps) / s.wall_time : 0.0;
  j["step_ms_median"] = s.step_ms_median;
  j["step_ms_p99"] = s.step_ms_p99;
  j["steps"] = s.steps;
  j["overruns"] = s.overruns;
  j["behind"] = s.behind;
  j["sim_time_s"] = s.sim_time;
  j["wall_time_s"] = s.wall_time;
  j["real_time_fraction"] = real_time_fraction(s);
  j["iterations"] = s.iterations;
  j["not_converged"] = s.not_converged;
  j["fraction_above_tolerance"] = fraction_above_tolerance(s);
  j["error"] = s.error;
  for (const auto& [key, value] : extra) j[key] = std::isfinite(value) ? nlohmann::ordered_json(value) : nullptr;
  write_file_atomically(path, [&](std::ostream& out) { out << j.dump(2) << '\n'; });
}

}  // namespace hooke::interactive
