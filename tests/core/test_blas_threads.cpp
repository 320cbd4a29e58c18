#include <gtest/gtest.h>

#include <omp.h>
#include <hooke/core/blas_threads.hpp>

namespace hooke {
namespace {

// Debian's OpenBLAS is the BLAS here (scripts/setup.sh): the counts (BLAS and OpenMP) are set, reported back and
// restored by the scope.
TEST(BlasThreads, TheScopeSetsOneThreadAndRestoresTheCount) {
  const int before = set_blas_threads(3);
  ASSERT_GT(before, 0) << "OpenBLAS's thread count was not found: is libopenblas0-pthread the system BLAS?";
  const int openmp_before = set_openmp_threads(3);
  {
    const ScopedThreadCount one;
    EXPECT_EQ(set_blas_threads(1), 1);
    EXPECT_EQ(omp_get_max_threads(), 1);
  }
  EXPECT_EQ(omp_get_max_threads(), 3);
  EXPECT_EQ(set_blas_threads(before), 3);
  EXPECT_EQ(set_blas_threads(0), 0);  // refused: nothing set
  set_openmp_threads(openmp_before);
}

}  // namespace
}  // namespace hooke
