#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <chrono>
#include <hooke/core/error.hpp>
#include <hooke/core/quantile.hpp>
#include <hooke/interactive/haptic_loop.hpp>

namespace hooke::interactive {
namespace {
using Clock = std::chrono::steady_clock;
}  // namespace

HapticLoop::HapticLoop(PhysicsLoop& physics, Device device, double rate_hz, bool record)
    : m_physics(physics), m_device(std::move(device)), m_period(1.0 / rate_hz), m_record(record) {
  if (!(rate_hz > 0.0) || !std::isfinite(rate_hz)) throw InvalidArgument("the haptic rate must be a number > 0 Hz");
  if (!m_device) throw InvalidArgument("a haptic loop needs a device");
  m_stats.target_rate = rate_hz;
  m_physics.enable_haptics();
}

HapticLoop::~HapticLoop() { stop(); }

void HapticLoop::start() {
  if (!m_thread.joinable()) {
    m_stop = false;
    m_thread = std::thread([this] { run(); });
  }
}

void HapticLoop::stop() {
  m_stop = true;
  if (m_thread.joinable()) m_thread.join();
}

HapticStats HapticLoop::stats() const {
  std::lock_guard lock(m_mutex);
  return m_stats;
}

VecX HapticLoop::force() const {
  std::lock_guard lock(m_mutex);
  return m_force;
}

ForceTrace HapticLoop::trace() const {
  std::lock_guard lock(m_mutex);
  ForceTrace out;
  out.time = m_times;
  const Eigen::Index d = m_forces.empty() ? 0 : m_forces.front().size();
  out.force.resize(static_cast<Eigen::Index>(m_forces.size()), d);
  for (size_t i = 0; i < m_forces.size(); ++i) out.force.row(static_cast<Eigen::Index>(i)) = m_forces[i].transpose();
  return out;
}

void HapticLoop::run() {
  // A real-time priority where the system grants one (root, or CAP_SYS_NICE): the deformation then never delays a
  // tick. Otherwise the thread runs at normal priority and its period percentiles say what that costs.
  sched_param param{};
  param.sched_priority = std::max(1, sched_get_priority_min(SCHED_FIFO));
  m_realtime_priority = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0;
  const Clock::time_point start = Clock::now();
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(m_period));
  Clock::time_point next = start, last_start = start;
  std::vector<double> periods, work;  // the last 10 000 ticks, ms
  constexpr size_t kWindow = 10000;
  periods.reserve(kWindow);
  work.reserve(kWindow);
  long ticks = 0, models = 0, last_version = -1;
  // The last ~200 us before a tick are spun, not slept: the scheduler's wake-up would otherwise add its latency to
  // every period.
  const auto spin = std::chrono::microseconds(200);
  while (!m_stop) {
    if (next - Clock::now() > spin) std::this_thread::sleep_until(next - spin);
    while (Clock::now() < next) {
    }
    const Clock::time_point t0 = Clock::now();
    const double t = std::chrono::duration<double>(t0 - start).count();
    const VecX device = m_device(t);
    const HapticModel model = m_physics.haptic_model();
    // No device input (an empty offset): the physics keeps its own probe offset (a script's drag) and the force is
    // the model's at that offset.
    const VecX force = model.render(device.size() > 0 ? device : model.offset);
    if (device.size() > 0) m_physics.set_device_offset(device);
    const Clock::time_point t1 = Clock::now();
    if (model.version != last_version) {
      last_version = model.version;
      ++models;
    }
    // Rings of the last kWindow values: no per-tick shifting of the window.
    const auto put = [](std::vector<double>& ring, long index, double value) {
      if (ring.size() < kWindow)
        ring.push_back(value);
      else
        ring[static_cast<size_t>(index) % kWindow] = value;
    };
    if (ticks > 0) put(periods, ticks - 1, std::chrono::duration<double, std::milli>(t0 - last_start).count());
    put(work, ticks, std::chrono::duration<double, std::milli>(t1 - t0).count());
    last_start = t0;
    ++ticks;
    {
      std::lock_guard lock(m_mutex);
      m_force = force;
      if (m_record) {
        m_times.push_back(t);
        m_forces.push_back(force);
      }
      m_stats.ticks = ticks;
      m_stats.realtime_priority = m_realtime_priority;
      m_stats.models = models;
      const double wall = std::chrono::duration<double>(t1 - start).count();
      m_stats.achieved_rate = wall > 0.0 ? static_cast<double>(ticks) / wall : 0.0;
      m_stats.model_rate = wall > 0.0 ? static_cast<double>(models) / wall : 0.0;
      if (ticks % 100 == 1) {  // percentiles now and then
        m_stats.period_ms_median = quantile(periods, 0.5);
        m_stats.period_ms_p99 = quantile(periods, 0.99);
        m_stats.tick_ms_median = quantile(work, 0.5);
        m_stats.tick_ms_p99 = quantile(work, 0.99);
      }
    }
    next += period;
    if (Clock::now() - next > 50 * period) next = Clock::now();  // far behind: no burst to catch up
  }
  std::lock_guard lock(m_mutex);
  m_stats.period_ms_median = quantile(periods, 0.5);
  m_stats.period_ms_p99 = quantile(periods, 0.99);
  m_stats.tick_ms_median = quantile(work, 0.5);
  m_stats.tick_ms_p99 = quantile(work, 0.99);
}

}  // namespace hooke::interactive
