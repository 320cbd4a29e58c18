#pragma once
/// The thread count of the BLAS under CHOLMOD's supernodal factorisation. Debian's OpenBLAS (libopenblas0-pthread)
/// runs its own threads, and its dense kernels block differently with more threads, so a factorisation's last bits
/// depend on the thread count (measured: relative errors of the nu-range study differ by 1e-14 to 1e-10 between one
/// and two BLAS threads; hooke's own OpenMP loops do not). Work that must give the same bits on any machine (the
/// nu-range study, serial or on Dask workers) runs the BLAS on one thread; on the study's meshes that is also faster
/// (one task 5.8 s against 6.6 s with two threads).

namespace hooke {

/// Sets the BLAS's thread count to `threads` (>= 1) and returns the previous one: OpenBLAS's, looked up at run time;
/// 0 (and nothing set) for a BLAS without a thread count. Process-wide: call it where no factorisation runs.
int set_blas_threads(int threads);

/// One BLAS thread (or `threads`) for the scope's lifetime; the previous count is restored at its end.
class ScopedBlasThreads {
 public:
  explicit ScopedBlasThreads(int threads = 1) : m_previous(set_blas_threads(threads)) {}
  ~ScopedBlasThreads() {
    if (m_previous > 0) set_blas_threads(m_previous);
  }
  ScopedBlasThreads(const ScopedBlasThreads&) = delete;
  ScopedBlasThreads& operator=(const ScopedBlasThreads&) = delete;

 private:
  int m_previous;
};

}  // namespace hooke
