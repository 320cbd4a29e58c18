#pragma once
/// A background job of which only the newest counts (the viewer's FEM ghost): submitting a job while an older one
/// still runs does not wait for it; the older one finishes in its own thread and its result is dropped. A front
/// end's frame never blocks on a solve it no longer needs.
///
/// One thread submits and takes (the front end); the jobs run in threads of their own.
#include <atomic>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace hooke::interactive {

template <typename T>
class LatestJob {
 public:
  LatestJob() = default;
  ~LatestJob() {  // waits for the jobs still running (their results are dropped)
    for (Worker& w : m_workers) w.thread.join();
  }
  LatestJob(const LatestJob&) = delete;
  LatestJob& operator=(const LatestJob&) = delete;

  /// Starts `job` in a thread of its own; it becomes the newest job (the result of any older one is dropped).
  /// Returns at once, whatever the older jobs are doing.
  void submit(std::function<T()> job) {
    reap();
    auto slot = std::make_shared<Slot>();
    m_current = slot;
    m_workers.push_back(Worker{std::thread([slot, job = std::move(job)] { slot->run(job); }), slot});
  }
  /// Runs `job` now in the calling thread; it becomes the newest job (for scripted runs that must wait).
  void run_now(const std::function<T()>& job) {
    reap();
    auto slot = std::make_shared<Slot>();
    slot->run(job);
    m_current = slot;
  }
  /// Drops the newest job: it finishes in its own thread and its result is never taken.
  void drop() { m_current.reset(); }
  /// The newest job has been submitted and not taken yet.
  bool pending() const { return m_current != nullptr; }
  /// The newest job's result once it is done, once: its value, or its exception rethrown. Empty while it runs, when
  /// there is none or it has been taken.
  std::optional<T> take() {
    if (!m_current || !m_current->done.load()) return std::nullopt;
    const std::shared_ptr<Slot> slot = std::move(m_current);
    m_current.reset();
    if (slot->error) std::rethrow_exception(slot->error);
    return std::move(slot->value);
  }

 private:
  struct Slot {
    std::atomic<bool> done{false};
    std::optional<T> value;    // written by the job's thread before done, read after done
    std::exception_ptr error;  // the same
    void run(const std::function<T()>& job) {
      try {
        value.emplace(job());
      } catch (...) {
        error = std::current_exception();
      }
      done.store(true);
    }
  };
  struct Worker {
    std::thread thread;
    std::shared_ptr<Slot> slot;
  };
  // Joins the threads whose job is done (at once: they have nothing left to do).
  void reap() {
    std::erase_if(m_workers, [](Worker& w) {
      if (!w.slot->done.load()) return false;
      w.thread.join();
      return true;
    });
  }

  std::shared_ptr<Slot> m_current;
  std::vector<Worker> m_workers;
};

}  // namespace hooke::interactive
