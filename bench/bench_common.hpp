#pragma once
// Shared by the benchmarks: the memory-bandwidth baseline and a per-size cache of expensive setups.
#include <benchmark/benchmark.h>

#include <chrono>
#include <map>
#include <memory>
#include <vector>

namespace hooke::bench {

/// Bandwidth of the fastest STREAM-like triad pass a[i] = b[i] + s c[i] of the last run_triad, bytes/s.
inline double& triad_bytes_per_second() {
  static double value = 0.0;
  return value;
}

/// Benchmark body of the triad over 3 x 16 M doubles (384 MB moved per pass, STREAM's count), on all OpenMP
/// threads as the force passes run: the machine's memory-bandwidth baseline, measured in the same run as what is
/// compared with it.
inline void run_triad(benchmark::State& state) {
  const size_t n = 1 << 24;
  std::vector<double> a(n), b(n), c(n);
#pragma omp parallel for schedule(static)  // first touch by the thread that streams the page later
  for (size_t i = 0; i < n; ++i) {
    a[i] = 0.0;
    b[i] = 1.0;
    c[i] = 2.0;
  }
  double best = 1e300;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; ++i) a[i] = b[i] + 3.0 * c[i];
    benchmark::DoNotOptimize(a.data());
    benchmark::ClobberMemory();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  triad_bytes_per_second() = 3.0 * n * sizeof(double) / best;
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(3 * n * sizeof(double)));
}

/// One T per size argument, built on first use and kept for the whole run.
template <typename T>
T& cached(int size) {
  static std::map<int, std::unique_ptr<T>> cache;
  auto& entry = cache[size];
  if (!entry) entry = std::make_unique<T>(size);
  return *entry;
}

}  // namespace hooke::bench
