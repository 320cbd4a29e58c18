#pragma once
/// A value several threads use, one at a time: with(f) runs f on it while no other thread does (e.g. Python's
/// hooke.LiveSimulation, stepped by one thread while a haptic device's thread drags). f must not let a reference
/// into the value escape: what it returns is a copy the lock no longer covers.
#include <mutex>
#include <utility>

namespace hooke::interactive {

template <typename T>
class Guarded {
 public:
  explicit Guarded(T value) : m_value(std::move(value)) {}
  Guarded(const Guarded&) = delete;
  Guarded& operator=(const Guarded&) = delete;

  /// f(value) under the lock; returns what f returns (by value).
  template <typename F>
  auto with(F&& f) {
    const std::lock_guard lock(m_mutex);
    return std::forward<F>(f)(m_value);
  }
  template <typename F>
  auto with(F&& f) const {
    const std::lock_guard lock(m_mutex);
    return std::forward<F>(f)(m_value);
  }

 private:
  mutable std::mutex m_mutex;
  T m_value;
};

}  // namespace hooke::interactive
