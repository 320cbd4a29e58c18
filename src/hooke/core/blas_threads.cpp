#include <dlfcn.h>
#include <omp.h>

#include <hooke/core/blas_threads.hpp>

namespace hooke {

int set_blas_threads(int threads) {
  using Get = int (*)();
  using Set = void (*)(int);
  // Looked up, not linked: the system BLAS may be another one (the reference BLAS has no threads).
  const auto get = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  const auto set = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (get == nullptr || set == nullptr || threads < 1) return 0;
  const int previous = get();
  set(threads);
  return previous;
}

int set_openmp_threads(int threads) {
  const int previous = omp_get_max_threads();
  if (threads >= 1) omp_set_num_threads(threads);
  return previous;
}

}  // namespace hooke
