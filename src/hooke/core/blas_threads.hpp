#pragma once
/// The thread counts under hooke's numerics: the BLAS's (CHOLMOD's supernodal factorisation) and OpenMP's (hooke's
/// own loops and Eigen's dense products). Debian's OpenBLAS (libopenblas0-pthread) runs its own threads, and its dense
/// kernels block differently with more threads; Eigen's products split their blocks by omp_get_max_threads(). So a
/// result's last bits depend on both counts (measured: relative errors of the nu-range study differ by 1e-14 to 1e-10
/// between one and two BLAS threads, and by 4e-13 between one and two OpenMP threads in stiffness-fit-volume's
/// self-weight scale). Work that must give the same bits on any machine (the nu-range study, serial or on Dask
/// workers, whose processes start with OMP_NUM_THREADS=1) runs on one thread of each; on the study's meshes that is
/// also faster (one task 5.8 s against 6.6 s with two BLAS threads).

namespace hooke {

/// Sets the BLAS's thread count to `threads` (>= 1) and returns the previous one: OpenBLAS's, looked up at run time;
/// 0 (and nothing set) for a BLAS without a thread count. Process-wide: call it where no factorisation runs.
int set_blas_threads(int threads);

/// Sets OpenMP's thread count for later parallel regions of the calling thread (omp_set_num_threads, >= 1) and
/// returns the previous omp_get_max_threads().
int set_openmp_threads(int threads);

/// One BLAS thread and one OpenMP thread (or `threads` of each) for the scope's lifetime; the previous counts are
/// restored at its end.
class ScopedThreadCount {
 public:
  explicit ScopedThreadCount(int threads = 1)
      : m_previous_blas(set_blas_threads(threads)), m_previous_openmp(set_openmp_threads(threads)) {}
  ~ScopedThreadCount() {
    if (m_previous_blas > 0) set_blas_threads(m_previous_blas);
    set_openmp_threads(m_previous_openmp);
  }
  ScopedThreadCount(const ScopedThreadCount&) = delete;
  ScopedThreadCount& operator=(const ScopedThreadCount&) = delete;

 private:
  int m_previous_blas, m_previous_openmp;
};

}  // namespace hooke
