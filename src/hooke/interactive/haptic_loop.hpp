#pragma once
/// The haptic half of multirate haptics (Cavusoglu & Tendick 2000): a thread of its own at a fixed rate (1 kHz by
/// default) beside a PhysicsLoop that deforms the whole body at its own rate. Every tick reads the device's offset,
/// renders the probe force from the physics' latest local model (HapticModel::render) and hands the offset to the
/// physics for its next step. Its rate, period jitter and tick time are measured, not assumed.
#include <atomic>
#include <functional>
#include <hooke/interactive/multirate.hpp>
#include <hooke/interactive/physics_loop.hpp>
#include <mutex>
#include <thread>

namespace hooke::interactive {

/// What the haptic thread achieved.
struct HapticStats {
  double target_rate = 0.0;       ///< ticks per second wanted, Hz
  double achieved_rate = 0.0;     ///< ticks per wall second since start(), Hz
  double period_ms_median = 0.0;  ///< wall time between two ticks' starts, ms
  double period_ms_p99 = 0.0;     ///< its 99th percentile, ms
  double tick_ms_median = 0.0;    ///< wall time of a tick's work (device, model, render, hand-over), ms
  double tick_ms_p99 = 0.0;       ///< its 99th percentile, ms
  long ticks = 0;
  long models = 0;                 ///< distinct local models received from the physics
  double model_rate = 0.0;         ///< models per wall second: the deformation's rate as the haptics sees it, Hz
  bool realtime_priority = false;  ///< the thread runs under SCHED_FIFO (granted to root or CAP_SYS_NICE)
};

class HapticLoop {
 public:
  /// The device: its offset (m, dim) at wall time t (s since start()); a scripted drag, or a driver's position. An
  /// empty vector: no input now (the physics keeps its probe's offset; the force rendered is the model's there).
  using Device = std::function<VecX(double)>;

  /// Attaches to `physics` (which must outlive this loop; enable_haptics() is called on it). `record` keeps every
  /// tick's time and force (trace()). @throws InvalidArgument for a rate <= 0 or no device
  HapticLoop(PhysicsLoop& physics, Device device, double rate_hz = 1000.0, bool record = false);
  ~HapticLoop();  ///< stops the thread
  HapticLoop(const HapticLoop&) = delete;
  HapticLoop& operator=(const HapticLoop&) = delete;

  void start();
  void stop();  ///< joins the thread; idempotent

  HapticStats stats() const;
  /// The last rendered force on the probe, N (dim; empty before the first tick).
  VecX force() const;
  /// Every tick's wall time (s since start()) and force, when recording.
  ForceTrace trace() const;

 private:
  void run();

  PhysicsLoop& m_physics;
  Device m_device;
  double m_period;
  bool m_record;
  bool m_realtime_priority = false;  // the haptic thread's own
  std::thread m_thread;
  std::atomic<bool> m_stop{false};
  mutable std::mutex m_mutex;  // guards what follows
  HapticStats m_stats;
  VecX m_force;
  std::vector<double> m_times;
  std::vector<VecX> m_forces;
};

}  // namespace hooke::interactive
