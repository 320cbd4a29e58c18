#include <dlfcn.h>
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

#include <omp.h>
#if defined(__x86_64__)
#include <immintrin.h>
#endif
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <hooke/core/detail/supernode_split.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/sparse_cholesky.hpp>
#include <list>
#include <mutex>
#include <type_traits>
#include <vector>

namespace hooke {

// Below this many unknowns kAuto uses Eigen's simplicial LDL^T: there CHOLMOD's supernodal path hands tiny
// dense blocks to a threaded BLAS whose threads spend their time waking and yielding. Measured on
// `hooke reproduce lloyd2007` (2 cores): CHOLMOD always 72 s wall; threshold 1 000: 66 s; threshold 5 000:
// 115 s (simplicial fill on the 3 000-DOF tet meshes costs more than the threads do).
constexpr Eigen::Index kSmallSystem = 1000;

namespace {

// CHOLMOD's supernodal factor's arrays: the permutation, each supernode's first column (super), its rows' start
// in rows (pi) and its values' start (px).
struct Supernodes {
  explicit Supernodes(const cholmod_factor& l)
      : n(static_cast<int>(l.n)),
        nsuper(static_cast<int>(l.nsuper)),
        perm(static_cast<const int*>(l.Perm)),
        super(static_cast<const int*>(l.super)),
        pi(static_cast<const int*>(l.pi)),
        px(static_cast<const int*>(l.px)),
        rows(static_cast<const int*>(l.s)) {}
  int n, nsuper;
  const int *perm, *super, *pi, *px, *rows;
};

// Runs group(0) and group(1) of a split on two threads (both on one where OMP_NUM_THREADS=1: the same operations,
// the same bits).
template <class F>
void on_two_groups(F&& group) {
  const int threads_wanted = std::min(2, omp_get_max_threads());
#pragma omp parallel num_threads(threads_wanted)
  for (int g = omp_get_thread_num(); g < 2; g += omp_get_num_threads()) group(static_cast<size_t>(g));
}

// L L^T x = b for CHOLMOD's supernodal factor of P A P^T, R right-hand sides interleaved in b. CHOLMOD's own solve
// goes through BLAS, whose small-matrix dgemm kernel in OpenBLAS 0.3.21 calls malloc on every call (caught by
// tests/solve/test_simulator_allocation.cpp); here each supernode's dense kernels are Eigen's vectorised triangular
// solve and matrix-vector products on maps of the factor (no allocation), one right-hand side at a time while the
// supernode is in cache. Measured on the benchmark cylinders' any-nu-tet rest matrices (2 cores, one thread):
// 3 267 DOFs 0.29 ms (the earlier hand-written loops 0.67 ms, cholmod_solve 0.35 ms), 3 right-hand sides 0.85 ms
// (2.7 ms); 34 275 DOFs 20 ms (30 ms). S is the factor's scalar: double (CHOLMOD's own values, lx = l.x) or float
// (a copy, half the memory traffic: 3 267 DOFs 0.25 ms against 0.40 ms in one run, 34 275 DOFs 13.8 against
// 22.2 ms). w: n x R work, column-major; t: max rows work.
//
// With a split (detail::SupernodeSplit, factors from 4 M entries), the two groups of independent subtrees run on two
// threads: in L y = P b the second group's updates of the top's rows go to its own buffer w2 (n x R, added after
// both), and in L^T z = y both groups only read the top's rows, solved first. The order of every operation is fixed
// by the split, not by the number of threads. t2: the second thread's max rows work.
template <class S>
void supernodal_solve(const cholmod_factor& l, const S* lx, double* b, S* w, S* t, int nrhs,
                      const detail::SupernodeSplit* split = nullptr, S* w2 = nullptr, S* t2 = nullptr) {
  using Block = Eigen::Map<const Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>, 0, Eigen::OuterStride<>>;
  using Vector = Eigen::Map<Eigen::Matrix<S, Eigen::Dynamic, 1>>;
  const Supernodes f(l);
  const int n = f.n, nsuper = f.nsuper;
  const int *perm = f.perm, *super = f.super, *pi = f.pi, *px = f.px, *rows = f.rows;
  for (int r = 0; r < nrhs; ++r)
    for (int k = 0; k < n; ++k) w[r * n + k] = static_cast<S>(b[nrhs * perm[k] + r]);
  // Supernode s holds columns k1 .. k1 + nsc - 1 as an nsrow x nsc column-major block: the diagonal block L11 on
  // top, L21 (rows srows[nsc ..]) below.
  auto blocks = [&](int s, auto&& body) {
    const int k1 = super[s], nsc = super[s + 1] - k1, nsrow = pi[s + 1] - pi[s], below = nsrow - nsc;
    const Block l11(lx + px[s], nsc, nsc, Eigen::OuterStride<>(nsrow));
    const Block l21(lx + px[s] + nsc, below, nsc, Eigen::OuterStride<>(nsrow));
    for (int r = 0; r < nrhs; ++r) body(r, k1, nsc, below, rows + pi[s] + nsc, l11, l21);
  };
  // L y = P b at supernode s; rows from `bound` on are updated in `spill` instead of w (null: none).
  auto forward = [&](int s, S* tw, int bound, S* spill) {
    blocks(s, [&](int r, int k1, int nsc, int below, const int* srows, const Block& l11, const Block& l21) {
      S* wr = w + r * n;
      Vector y(wr + k1, nsc);
      l11.template triangularView<Eigen::Lower>().solveInPlace(y);
      if (below == 0) return;
      Vector(tw, below).noalias() = l21 * y;
      const int inside = spill ? static_cast<int>(std::lower_bound(srows, srows + below, bound) - srows) : below;
      for (int i = 0; i < inside; ++i) wr[srows[i]] -= tw[i];
      for (int i = inside; i < below; ++i) spill[r * n + srows[i]] += tw[i];
    });
  };
  auto backward = [&](int s, S* tw) {  // L^T z = y at supernode s
    blocks(s, [&](int r, int k1, int nsc, int below, const int* srows, const Block& l11, const Block& l21) {
      S* wr = w + r * n;
      Vector y(wr + k1, nsc);
      if (below > 0) {
        for (int i = 0; i < below; ++i) tw[i] = wr[srows[i]];
        y.noalias() -= l21.transpose() * Vector(tw, below);
      }
      l11.transpose().template triangularView<Eigen::Upper>().solveInPlace(y);
    });
  };
  if (split == nullptr || !split->parallel()) {
    for (int s = 0; s < nsuper; ++s) forward(s, t, 0, nullptr);
    for (int s = nsuper - 1; s >= 0; --s) backward(s, t);
  } else {
    for (int r = 0; r < nrhs; ++r)
      for (int k : split->top_columns) w2[r * n + k] = S(0);
    on_two_groups([&](size_t g) {
      for (const auto& [first, last] : split->ranges[g])
        for (int s = first; s <= last; ++s)
          forward(s, g == 0 ? t : t2, g == 0 ? 0 : super[last + 1], g == 0 ? nullptr : w2);
    });
    for (int r = 0; r < nrhs; ++r)
      for (int k : split->top_columns) w[r * n + k] -= w2[r * n + k];
    for (int s : split->top) forward(s, t, 0, nullptr);
    for (auto it = split->top.rbegin(); it != split->top.rend(); ++it) backward(*it, t);
    on_two_groups([&](size_t g) {
      for (auto range = split->ranges[g].rbegin(); range != split->ranges[g].rend(); ++range)
        for (int s = (*range)[1]; s >= (*range)[0]; --s) backward(s, g == 0 ? t : t2);
    });
  }
  for (int r = 0; r < nrhs; ++r)
    for (int k = 0; k < n; ++k) b[nrhs * perm[k] + r] = w[r * n + k];
}

// bfloat16: a float's upper 16 bits (8 significant bits, float's exponent range). Rounded to nearest, ties to
// even; widening back is a shift, which compilers vectorise without F16C.
std::uint16_t to_bfloat16(double x) {
  const auto u = std::bit_cast<std::uint32_t>(static_cast<float>(x));
  return static_cast<std::uint16_t>((u + 0x7FFFu + ((u >> 16) & 1u)) >> 16);
}
inline float from_bfloat16(std::uint16_t h) { return std::bit_cast<float>(static_cast<std::uint32_t>(h) << 16); }

// A supernode's rows of w (interleaved, n x R) gathered into t, one plane of nsrow rows per right-hand side
// (t[r * nsrow + i]: contiguous rows, which the kernels' loops vectorise); with `spill`, the rows from `bound` on
// start from 0 instead (their updates go to spill). Returns how many rows come from w.
template <int R>
[[gnu::always_inline]] inline int gather_rows(const int* srows, int nsrow, const float* w, float* t, int bound,
                                              const float* spill) {
  const int inside = spill ? static_cast<int>(std::lower_bound(srows, srows + nsrow, bound) - srows) : nsrow;
  for (int i = 0; i < inside; ++i)
    for (int r = 0; r < R; ++r) t[r * nsrow + i] = w[R * srows[i] + r];
  for (int i = inside; i < nsrow; ++i)
    for (int r = 0; r < R; ++r) t[r * nsrow + i] = 0.0f;
  return inside;
}
// t scattered back: the first `inside` rows to w, the others added to spill.
template <int R>
[[gnu::always_inline]] inline void scatter_rows(const int* srows, int nsrow, int inside, const float* t, float* w,
                                                float* spill) {
  for (int i = 0; i < inside; ++i)
    for (int r = 0; r < R; ++r) w[R * srows[i] + r] = t[r * nsrow + i];
  for (int i = inside; i < nsrow; ++i)
    for (int r = 0; r < R; ++r) spill[R * srows[i] + r] += t[r * nsrow + i];
}

// supernodal_solve on a bfloat16 copy of the factor, in float arithmetic: a quarter of the double factor's memory
// traffic. It solves exactly (up to float round-off) with L~ L~^T, L~ the factor rounded to bfloat16, so it is
// the inverse of a symmetric positive-definite matrix within about 4e-3 of A on the benchmark cylinders' rest
// matrices (docs/simulation.md): a preconditioner or quasi-Newton initial Hessian, never a solution. Each
// supernode's rows are gathered into t (gather_rows), its columns applied as contiguous axpys (forward) and dot
// products (backward), and scattered back. w: n x R work, interleaved; t: (max rows) x R.
//
// L y = P b at supernode s. With `spill` (the second group of a split), the rows from `bound` on (the top's) start
// from 0 and their updates are added to spill instead of w, which the first group writes at the same time.
template <int R>
[[gnu::always_inline]] inline void bfloat16_forward(const Supernodes& f, const std::uint16_t* lx, int s, float* w,
                                                    float* t, int bound, float* spill) {
  const int nsc = f.super[s + 1] - f.super[s], nsrow = f.pi[s + 1] - f.pi[s];
  const int* srows = f.rows + f.pi[s];
  const int inside = gather_rows<R>(srows, nsrow, w, t, bound, spill);
  for (int j = 0; j < nsc; ++j) {
    const std::uint16_t* col = lx + f.px[s] + static_cast<std::ptrdiff_t>(j) * nsrow;
    const float d = from_bfloat16(col[j]);
    for (int r = 0; r < R; ++r) {
      float* tr = t + r * nsrow;
      const float y = tr[j] /= d;
      for (int i = j + 1; i < nsrow; ++i) tr[i] -= from_bfloat16(col[i]) * y;
    }
  }
  scatter_rows<R>(srows, nsrow, inside, t, w, spill);
}

// L^T z = y at supernode s: reads its rows of w, writes only its own columns.
template <int R>
[[gnu::always_inline]] inline void bfloat16_backward(const Supernodes& f, const std::uint16_t* lx, int s, float* w,
                                                     float* t) {
  const int nsc = f.super[s + 1] - f.super[s], nsrow = f.pi[s + 1] - f.pi[s];
  const int* srows = f.rows + f.pi[s];
  gather_rows<R>(srows, nsrow, w, t, 0, nullptr);
  for (int j = nsc - 1; j >= 0; --j) {
    const std::uint16_t* col = lx + f.px[s] + static_cast<std::ptrdiff_t>(j) * nsrow;
    const float d = from_bfloat16(col[j]);
    for (int r = 0; r < R; ++r) {
      float* tr = t + r * nsrow;
      // kLanes partial sums: float addition is not associative, so one running sum would not vectorise.
      constexpr int kLanes = 16;
      float lanes[kLanes] = {};
      int i = j + 1;
      for (; i + kLanes <= nsrow; i += kLanes)
        for (int q = 0; q < kLanes; ++q) lanes[q] += from_bfloat16(col[i + q]) * tr[i + q];
      float sum = 0.0f;
      for (; i < nsrow; ++i) sum += from_bfloat16(col[i]) * tr[i];
      for (int q = 0; q < kLanes; ++q) sum += lanes[q];
      tr[j] = (tr[j] - sum) / d;
    }
  }
  for (int c = 0; c < nsc; ++c)
    for (int r = 0; r < R; ++r) w[R * srows[c] + r] = t[r * nsrow + c];
}

// The supernode kernels compiled twice: for the baseline x86-64 (SSE2) and for AVX2, picked at run time. Without
// the wider vectors the widening and the products bound it: 34 275 DOFs 11.5 ms with SSE2, 8.6 ms with AVX2 (float
// copy 11.3-13.7 ms, double 23-27 ms, one thread, the same run). Both builds add in the same order. One right-hand
// side (quasi-Newton's rest H0) has its own AVX2 + FMA kernels below.
template <int R>
struct Bfloat16Kernels {
  void (*forward)(const Supernodes&, const std::uint16_t*, int, float*, float*, int, float*);
  void (*backward)(const Supernodes&, const std::uint16_t*, int, float*, float*);
};
template <int R>
void bfloat16_forward_baseline(const Supernodes& f, const std::uint16_t* lx, int s, float* w, float* t, int bound,
                               float* spill) {
  bfloat16_forward<R>(f, lx, s, w, t, bound, spill);
}
template <int R>
void bfloat16_backward_baseline(const Supernodes& f, const std::uint16_t* lx, int s, float* w, float* t) {
  bfloat16_backward<R>(f, lx, s, w, t);
}
#if defined(__x86_64__) && defined(__GNUC__)
template <int R>
[[gnu::target("avx2")]] void bfloat16_forward_avx2(const Supernodes& f, const std::uint16_t* lx, int s, float* w,
                                                   float* t, int bound, float* spill) {
  bfloat16_forward<R>(f, lx, s, w, t, bound, spill);
}
template <int R>
[[gnu::target("avx2")]] void bfloat16_backward_avx2(const Supernodes& f, const std::uint16_t* lx, int s, float* w,
                                                    float* t) {
  bfloat16_backward<R>(f, lx, s, w, t);
}

// One right-hand side with AVX2 and FMA, by hand (GCC's vectoriser gathers the 16-bit values one by one when
// several columns share a loop): kBlock columns at a time, so that each row below them is loaded and stored once
// for all of them (forward) or loaded once for their kBlock dot products (backward). 34 275 DOFs (the 11 425-node
// benchmark cylinder's rest matrix), the same run: the generic AVX2 kernel 12.9-13.1 ms, this one 11.3 ms, and
// 5.8-7.3 ms with the two-thread split (docs/simulation.md).
constexpr int kBlock = 4;

[[gnu::target("avx2,fma")]] inline __m256 bfloat16x8(const std::uint16_t* p) {
  const __m128i h = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
  return _mm256_castsi256_ps(_mm256_slli_epi32(_mm256_cvtepu16_epi32(h), 16));
}
[[gnu::target("avx2,fma")]] inline float sum8(__m256 v) {
  const __m128 q = _mm_add_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
  const __m128 h = _mm_add_ps(q, _mm_movehl_ps(q, q));
  return _mm_cvtss_f32(_mm_add_ss(h, _mm_shuffle_ps(h, h, 1)));
}

[[gnu::target("avx2,fma")]] void bfloat16_forward_fma(const Supernodes& f, const std::uint16_t* lx, int s, float* w,
                                                      float* t, int bound, float* spill) {
  const int nsc = f.super[s + 1] - f.super[s], nsrow = f.pi[s + 1] - f.pi[s];
  const int* srows = f.rows + f.pi[s];
  const int inside = gather_rows<1>(srows, nsrow, w, t, bound, spill);
  const std::uint16_t* x = lx + f.px[s];
  int j = 0;
  for (; j + kBlock <= nsc; j += kBlock) {
    const std::uint16_t* col[kBlock];
    float y[kBlock];
    __m256 yv[kBlock];
    for (int q = 0; q < kBlock; ++q) {
      col[q] = x + static_cast<std::ptrdiff_t>(j + q) * nsrow;
      y[q] = t[j + q] /= from_bfloat16(col[q][j + q]);
      yv[q] = _mm256_set1_ps(y[q]);
      for (int i = j + q + 1; i < j + kBlock; ++i) t[i] -= from_bfloat16(col[q][i]) * y[q];
    }
    int i = j + kBlock;
    for (; i + 8 <= nsrow; i += 8) {
      __m256 v = _mm256_loadu_ps(t + i);
      for (int q = 0; q < kBlock; ++q) v = _mm256_fnmadd_ps(bfloat16x8(col[q] + i), yv[q], v);
      _mm256_storeu_ps(t + i, v);
    }
    for (; i < nsrow; ++i)
      for (int q = 0; q < kBlock; ++q) t[i] -= from_bfloat16(col[q][i]) * y[q];
  }
  for (; j < nsc; ++j) {
    const std::uint16_t* col = x + static_cast<std::ptrdiff_t>(j) * nsrow;
    const float y = t[j] /= from_bfloat16(col[j]);
    const __m256 yv = _mm256_set1_ps(y);
    int i = j + 1;
    for (; i + 8 <= nsrow; i += 8)
      _mm256_storeu_ps(t + i, _mm256_fnmadd_ps(bfloat16x8(col + i), yv, _mm256_loadu_ps(t + i)));
    for (; i < nsrow; ++i) t[i] -= from_bfloat16(col[i]) * y;
  }
  scatter_rows<1>(srows, nsrow, inside, t, w, spill);
}

[[gnu::target("avx2,fma")]] void bfloat16_backward_fma(const Supernodes& f, const std::uint16_t* lx, int s, float* w,
                                                       float* t) {
  const int nsc = f.super[s + 1] - f.super[s], nsrow = f.pi[s + 1] - f.pi[s];
  const int* srows = f.rows + f.pi[s];
  gather_rows<1>(srows, nsrow, w, t, 0, nullptr);
  const std::uint16_t* x = lx + f.px[s];
  int j = nsc - 1;
  for (; j >= 0 && (j + 1) % kBlock != 0; --j) {  // the last nsc % kBlock columns one at a time
    const std::uint16_t* col = x + static_cast<std::ptrdiff_t>(j) * nsrow;
    __m256 a0 = _mm256_setzero_ps(), a1 = _mm256_setzero_ps();
    int i = j + 1;
    for (; i + 16 <= nsrow; i += 16) {
      a0 = _mm256_fmadd_ps(bfloat16x8(col + i), _mm256_loadu_ps(t + i), a0);
      a1 = _mm256_fmadd_ps(bfloat16x8(col + i + 8), _mm256_loadu_ps(t + i + 8), a1);
    }
    float sum = sum8(_mm256_add_ps(a0, a1));
    for (; i < nsrow; ++i) sum += from_bfloat16(col[i]) * t[i];
    t[j] = (t[j] - sum) / from_bfloat16(col[j]);
  }
  for (; j >= 0; j -= kBlock) {
    const int j0 = j - kBlock + 1;  // the block's first column
    const std::uint16_t* col[kBlock];
    __m256 acc[kBlock];
    for (int q = 0; q < kBlock; ++q) {
      col[q] = x + static_cast<std::ptrdiff_t>(j0 + q) * nsrow;
      acc[q] = _mm256_setzero_ps();
    }
    int i = j0 + kBlock;
    for (; i + 8 <= nsrow; i += 8) {
      const __m256 tv = _mm256_loadu_ps(t + i);
      for (int q = 0; q < kBlock; ++q) acc[q] = _mm256_fmadd_ps(bfloat16x8(col[q] + i), tv, acc[q]);
    }
    float sum[kBlock];
    for (int q = 0; q < kBlock; ++q) {
      sum[q] = sum8(acc[q]);
      for (int k = i; k < nsrow; ++k) sum[q] += from_bfloat16(col[q][k]) * t[k];
    }
    for (int q = kBlock - 1; q >= 0; --q) {
      for (int k = j0 + q + 1; k < j0 + kBlock; ++k) sum[q] += from_bfloat16(col[q][k]) * t[k];
      t[j0 + q] = (t[j0 + q] - sum[q]) / from_bfloat16(col[q][j0 + q]);
    }
  }
  for (int c = 0; c < nsc; ++c) w[srows[c]] = t[c];
}
#endif

template <int R>
Bfloat16Kernels<R> bfloat16_kernels() {
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool avx2 = __builtin_cpu_supports("avx2"), fma = __builtin_cpu_supports("fma");
  if constexpr (R == 1)
    if (avx2 && fma) return {bfloat16_forward_fma, bfloat16_backward_fma};
  if (avx2) return {bfloat16_forward_avx2<R>, bfloat16_backward_avx2<R>};
#endif
  return {bfloat16_forward_baseline<R>, bfloat16_backward_baseline<R>};
}

// The whole bfloat16 solve, on two threads with a split as supernodal_solve (w2: the second group's n x R buffer,
// t2: its rows work), on one without. The order of every operation is fixed by the split, not by the threads.
template <int R>
void supernodal_solve_bfloat16(const cholmod_factor& l, const std::uint16_t* lx, double* b, float* w, float* t,
                               const detail::SupernodeSplit* split = nullptr, float* w2 = nullptr,
                               float* t2 = nullptr) {
  const Supernodes f(l);
  const Bfloat16Kernels<R> k = bfloat16_kernels<R>();
  for (int c = 0; c < f.n; ++c)
    for (int r = 0; r < R; ++r) w[R * c + r] = static_cast<float>(b[R * f.perm[c] + r]);
  if (split == nullptr || !split->parallel()) {
    for (int s = 0; s < f.nsuper; ++s) k.forward(f, lx, s, w, t, 0, nullptr);
    for (int s = f.nsuper - 1; s >= 0; --s) k.backward(f, lx, s, w, t);
  } else {
    for (int c : split->top_columns)
      for (int r = 0; r < R; ++r) w2[R * c + r] = 0.0f;
    on_two_groups([&](size_t g) {
      for (const auto& [first, last] : split->ranges[g])
        for (int s = first; s <= last; ++s)
          k.forward(f, lx, s, w, g == 0 ? t : t2, g == 0 ? 0 : f.super[last + 1], g == 0 ? nullptr : w2);
    });
    for (int c : split->top_columns)
      for (int r = 0; r < R; ++r) w[R * c + r] += w2[R * c + r];
    for (int s : split->top) k.forward(f, lx, s, w, t, 0, nullptr);
    for (auto it = split->top.rbegin(); it != split->top.rend(); ++it) k.backward(f, lx, *it, w, t);
    on_two_groups([&](size_t g) {
      for (auto range = split->ranges[g].rbegin(); range != split->ranges[g].rend(); ++range)
        for (int s = (*range)[1]; s >= (*range)[0]; --s) k.backward(f, lx, s, w, g == 0 ? t : t2);
    });
  }
  for (int c = 0; c < f.n; ++c)
    for (int r = 0; r < R; ++r) b[R * f.perm[c] + r] = w[R * c + r];
}

// The fill-reducing orderings CHOLMOD chose for the last few sparsity patterns, shared by every SparseCholesky in
// the process. CHOLMOD's default analysis tries AMD and then METIS on large 3D meshes: 1.34 s of a 1.50 s analysis
// on the Stanford bunny's model (233 373 DOFs, 9M nonzeros), against 0.16 s for the symbolic factorisation with
// the ordering given. A calibration and its certificate analyse the same pattern many times from different
// solvers (the scale fit, the FEM reference, each load case's Newton, each stability test), so the ordering is
// computed once. Given CHOLMOD's own postordered permutation back, the analysis returns that permutation
// unchanged, so the factor, and every result, is the same bits as with a fresh analysis (test).
class OrderingCache {
 public:
  static OrderingCache& instance() {
    static OrderingCache cache;
    return cache;
  }
  // A fingerprint of the pattern of `a`: its size, nonzero count and a 64-bit hash of its index arrays.
  struct Key {
    Eigen::Index rows = 0, nonzeros = 0;
    std::uint64_t hash = 0;
    bool operator==(const Key&) const = default;
  };
  static Key key_of(const SparseMatrix& a) {
    std::uint64_t h = 1469598103934665603ULL;  // FNV-1a over 32-bit words
    auto mix = [&h](const int* p, Eigen::Index count) {
      for (Eigen::Index i = 0; i < count; ++i) {
        h ^= static_cast<std::uint32_t>(p[i]);
        h *= 1099511628211ULL;
      }
    };
    mix(a.outerIndexPtr(), a.outerSize() + 1);
    mix(a.innerIndexPtr(), a.nonZeros());
    return {a.rows(), a.nonZeros(), h};
  }
  // The permutation stored for `key`, or empty.
  std::vector<int> find(const Key& key) {
    std::lock_guard lock(m_mutex);
    for (auto it = m_entries.begin(); it != m_entries.end(); ++it)
      if (it->first == key) {
        m_entries.splice(m_entries.begin(), m_entries, it);  // most recently used first
        return it->second;
      }
    return {};
  }
  void store(const Key& key, std::vector<int> perm) {
    std::lock_guard lock(m_mutex);
    m_entries.emplace_front(key, std::move(perm));
    if (m_entries.size() > kCapacity) m_entries.pop_back();
  }

 private:
  static constexpr size_t kCapacity = 4;
  std::mutex m_mutex;
  std::list<std::pair<Key, std::vector<int>>> m_entries;
};

// Eigen's CHOLMOD wrapper with access to its factor, for the allocation-free supernodal solve, and an analysis
// that reuses OrderingCache's permutation.
class CholmodLLT : public Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> {
 public:
  cholmod_factor* factor() const { return m_cholmodFactor; }

  // Symbolic analysis of the pattern of `a` (both triangles stored), with the cached ordering when there is one.
  // A hash collision would only hand CHOLMOD another valid permutation of the same size: more fill, same factor.
  // @return true when the cached ordering was used
  bool analyze_pattern(const SparseMatrix& a) {
    cholmod_common& common = cholmod();
    const OrderingCache::Key key = OrderingCache::key_of(a);
    std::vector<int> perm = OrderingCache::instance().find(key);
    if (perm.empty()) {
      analyzePattern(a);
      const cholmod_factor& l = *m_cholmodFactor;
      const auto* p = static_cast<const int*>(l.Perm);
      if (common.status == CHOLMOD_OK && p != nullptr)
        OrderingCache::instance().store(key, std::vector<int>(p, p + l.n));
      return false;
    }
    if (m_cholmodFactor) cholmod_free_factor(&m_cholmodFactor, &common);
    cholmod_sparse view = Eigen::viewAsCholmod(a.selfadjointView<Eigen::Lower>());
    const int methods = common.nmethods, ordering = common.method[0].ordering;
    common.nmethods = 1;
    common.method[0].ordering = CHOLMOD_GIVEN;
    m_cholmodFactor = cholmod_analyze_p(&view, perm.data(), nullptr, 0, &common);
    common.nmethods = methods;
    common.method[0].ordering = ordering;
    if (m_cholmodFactor == nullptr) throw SolverFailure("SparseCholesky: CHOLMOD's symbolic analysis failed");
    m_isInitialized = true;
    m_info = Eigen::Success;
    m_analysisIsOk = true;
    m_factorizationIsOk = false;
    return true;
  }
};

// A simplicial LL^T factor of P A P^T in compressed columns, diagonal entry first in each column.
struct SimplicialFactor {
  std::vector<int> start, row, old_of_new;
  std::vector<double> value;
  mutable VecX work;  // n x nrhs, interleaved

  template <int R>
  void solve(double* b) const {
    const auto n = static_cast<int>(old_of_new.size());
    if (work.size() < static_cast<Eigen::Index>(n) * R) work.resize(static_cast<Eigen::Index>(n) * R);
    double* w = work.data();
    for (int k = 0; k < n; ++k)
      for (int r = 0; r < R; ++r) w[R * k + r] = b[R * old_of_new[static_cast<size_t>(k)] + r];
    for (int j = 0; j < n; ++j) {  // L y = P b, by columns
      const int first = start[static_cast<size_t>(j)], last = start[static_cast<size_t>(j) + 1];
      double yj[R];
      for (int r = 0; r < R; ++r) yj[r] = w[R * j + r] /= value[static_cast<size_t>(first)];
      for (int q = first + 1; q < last; ++q) {
        const double l = value[static_cast<size_t>(q)];
        double* wi = w + R * row[static_cast<size_t>(q)];
        for (int r = 0; r < R; ++r) wi[r] -= l * yj[r];
      }
    }
    for (int j = n - 1; j >= 0; --j) {  // L^T z = y, by rows of L^T = columns of L
      const int first = start[static_cast<size_t>(j)], last = start[static_cast<size_t>(j) + 1];
      double zj[R];
      for (int r = 0; r < R; ++r) zj[r] = w[R * j + r];
      for (int q = first + 1; q < last; ++q) {
        const double l = value[static_cast<size_t>(q)];
        const double* wi = w + R * row[static_cast<size_t>(q)];
        for (int r = 0; r < R; ++r) zj[r] -= l * wi[r];
      }
      for (int r = 0; r < R; ++r) w[R * j + r] = zj[r] / value[static_cast<size_t>(first)];
    }
    for (int k = 0; k < n; ++k)
      for (int r = 0; r < R; ++r) b[R * old_of_new[static_cast<size_t>(k)] + r] = w[R * k + r];
  }
};

}  // namespace

struct SparseCholesky::Impl {
  CholeskyBackend requested, backend;
  CholmodLLT cholmod;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt;
  Eigen::Index rows = -1, nonzeros = -1;
  bool analyzed = false, ok = false, reused_ordering = false;
  mutable SimplicialFactor simplicial;
  mutable bool extracted = false;
  mutable VecX supernodal_work, supernodal_rows;       // n x 3 and the largest supernode's rows
  SolvePrecision precision = SolvePrecision::kDouble;  // of solve_in_place on the CHOLMOD backend
  std::vector<float> single_x;                         // kSingle's copy of the factor, made at factorize()
  std::vector<std::uint16_t> brain_x;                  // kBfloat16's copy
  mutable std::vector<float> single_work, single_rows;
  size_t max_super_rows = 0;            // the most rows of any supernode (diagonal block included), at copy_factor()
  detail::SupernodeSplit split;         // of the analysed factor's tree, for two-thread solves (empty: serial)
  mutable VecX split_work, split_rows;  // the second group's buffer and rows work (double)
  mutable std::vector<float> single_split_work, single_split_rows;  // (float)

  // Factors from this many entries solve on two threads where the tree splits evenly (the bunny's model, 7.5e7
  // entries; the 11 425-node benchmark cylinder, 1.9e7), smaller ones on one (a parallel region costs ~10 us).
  static constexpr long long kSplitEntries = 4'000'000;

  void split_tree() {
    const cholmod_factor& l = *cholmod.factor();
    split = l.is_super
                ? detail::split_supernodes(static_cast<int>(l.nsuper), static_cast<const int*>(l.super),
                                           static_cast<const int*>(l.pi), static_cast<const int*>(l.s), kSplitEntries)
                : detail::SupernodeSplit{};
  }

  // @pre `use` is kDouble or the precision whose copy copy_factor() made
  void cholmod_solve_in_place(double* b, int nrhs, SolvePrecision use) const {
    const cholmod_factor& l = *cholmod.factor();
    if (!l.is_super) throw SolverFailure("SparseCholesky: CHOLMOD returned a simplicial factor");
    const auto work = 3 * static_cast<size_t>(l.n), rows_work = static_cast<size_t>(l.maxesize) + 1;
    if (use != SolvePrecision::kDouble) {
      if (single_work.size() != work || single_rows.size() < 3 * max_super_rows) {
        single_work.resize(work);
        single_rows.resize(std::max(rows_work, 3 * max_super_rows));
      }
      float* w = single_work.data();
      float* t = single_rows.data();
      if (split.parallel() && (single_split_work.size() != work || single_split_rows.size() < 3 * max_super_rows)) {
        single_split_work.resize(work);
        single_split_rows.resize(std::max(rows_work, 3 * max_super_rows));
      }
      float *w2 = single_split_work.data(), *t2 = single_split_rows.data();
      if (use == SolvePrecision::kSingle)
        supernodal_solve(l, single_x.data(), b, w, t, nrhs, &split, w2, t2);
      else if (nrhs == 1)
        supernodal_solve_bfloat16<1>(l, brain_x.data(), b, w, t, &split, w2, t2);
      else if (nrhs == 2)
        supernodal_solve_bfloat16<2>(l, brain_x.data(), b, w, t, &split, w2, t2);
      else
        supernodal_solve_bfloat16<3>(l, brain_x.data(), b, w, t, &split, w2, t2);
      return;
    }
    if (supernodal_work.size() != static_cast<Eigen::Index>(work)) {
      supernodal_work.resize(static_cast<Eigen::Index>(work));
      supernodal_rows.resize(static_cast<Eigen::Index>(rows_work));
    }
    if (split.parallel() && split_work.size() != static_cast<Eigen::Index>(work)) {
      split_work.resize(static_cast<Eigen::Index>(work));
      split_rows.resize(static_cast<Eigen::Index>(rows_work));
    }
    supernodal_solve(l, static_cast<const double*>(l.x), b, supernodal_work.data(), supernodal_rows.data(), nrhs,
                     &split, split_work.data(), split_rows.data());
  }

  // The reduced-precision copy of CHOLMOD's supernodal factor values that `precision` asks for; frees the other.
  // @pre a successful CHOLMOD factorisation
  void copy_factor() {
    const cholmod_factor& l = *cholmod.factor();
    if (!l.is_super) throw SolverFailure("SparseCholesky: CHOLMOD returned a simplicial factor");
    const auto* x = static_cast<const double*>(l.x);
    const int* pi = static_cast<const int*>(l.pi);
    max_super_rows = 0;
    for (size_t k = 0; k < l.nsuper; ++k)
      max_super_rows = std::max(max_super_rows, static_cast<size_t>(pi[k + 1] - pi[k]));
    if (precision == SolvePrecision::kSingle)
      single_x.assign(x, x + l.xsize);
    else
      single_x = {};
    if (precision == SolvePrecision::kBfloat16) {
      brain_x.resize(l.xsize);
      std::transform(x, x + l.xsize, brain_x.begin(), to_bfloat16);
    } else {
      brain_x = {};
    }
  }

  // Copies Eigen's current factor into `simplicial` (LL^T of P A P^T). @pre backend == kEigen
  void extract() const {
    SimplicialFactor& f = simplicial;
    // Eigen keeps L unit lower (diagonal not stored) and D; LL^T form: columns of L scaled by sqrt(D).
    const auto& lower = ldlt.matrixL().nestedExpression();
    const VecX& d = ldlt.vectorD();
    const auto n = static_cast<size_t>(lower.cols());
    f.start.assign(1, 0);
    f.row.clear();
    f.value.clear();
    for (Eigen::Index j = 0; j < lower.cols(); ++j) {
      const double root = std::sqrt(d(j));
      f.row.push_back(static_cast<int>(j));
      f.value.push_back(root);
      for (std::remove_cvref_t<decltype(lower)>::InnerIterator it(lower, j); it; ++it)
        if (it.row() > j) {
          f.row.push_back(static_cast<int>(it.row()));
          f.value.push_back(it.value() * root);
        }
      f.start.push_back(static_cast<int>(f.row.size()));
    }
    f.old_of_new.resize(n);
    const auto& p = ldlt.permutationP().indices();  // Eigen factors P A P^T with (P b)(p(i)) = b(i)
    if (p.size() == 0)
      for (size_t i = 0; i < n; ++i) f.old_of_new[i] = static_cast<int>(i);
    else
      for (Eigen::Index i = 0; i < p.size(); ++i) f.old_of_new[static_cast<size_t>(p(i))] = static_cast<int>(i);
    extracted = true;
  }
};

SparseCholesky::SparseCholesky(CholeskyBackend backend) : m_impl(std::make_unique<Impl>()) {
  m_impl->requested = backend;
  m_impl->backend = backend == CholeskyBackend::kAuto ? CholeskyBackend::kCholmod : backend;
  // CHOLMOD reports a non-positive-definite matrix through its status; keep it from printing.
  m_impl->cholmod.cholmod().print = 0;
}

SparseCholesky::~SparseCholesky() = default;
SparseCholesky::SparseCholesky(SparseCholesky&&) noexcept = default;
SparseCholesky& SparseCholesky::operator=(SparseCholesky&&) noexcept = default;

bool SparseCholesky::factorize(const SparseMatrix& a) {
  Impl& s = *m_impl;
  const bool same_pattern = s.analyzed && a.rows() == s.rows && a.nonZeros() == s.nonzeros;
  if (!same_pattern && s.requested == CholeskyBackend::kAuto)
    s.backend = a.rows() < kSmallSystem ? CholeskyBackend::kEigen : CholeskyBackend::kCholmod;
  if (s.backend == CholeskyBackend::kCholmod) {
    if (!same_pattern) {
      s.reused_ordering = s.cholmod.analyze_pattern(a);
      s.split_tree();
    }
    s.cholmod.factorize(a);
    s.ok = s.cholmod.info() == Eigen::Success;
    if (s.ok && s.precision != SolvePrecision::kDouble) s.copy_factor();
  } else {
    if (!same_pattern) {
      s.ldlt.analyzePattern(a);
      s.reused_ordering = false;  // Eigen's ordering is never shared
    }
    s.ldlt.factorize(a);
    // LDL^T succeeds on indefinite matrices; positive definiteness needs every pivot positive.
    s.ok = s.ldlt.info() == Eigen::Success && (s.ldlt.vectorD().array() > 0.0).all();
  }
  s.extracted = false;
  s.rows = a.rows();
  s.nonzeros = a.nonZeros();
  s.analyzed = true;
  return s.ok;
}

VecX SparseCholesky::solve(const VecX& b) const {
  if (!m_impl->ok) throw SolverFailure("SparseCholesky::solve called without a successful factorisation");
  if (m_impl->backend == CholeskyBackend::kCholmod) return m_impl->cholmod.solve(b);
  return m_impl->ldlt.solve(b);
}

void SparseCholesky::solve_in_place(double* b, int nrhs) const { solve_in_place(b, nrhs, m_impl->precision); }

void SparseCholesky::solve_exact_in_place(double* b, int nrhs) const {
  solve_in_place(b, nrhs, SolvePrecision::kDouble);
}

void SparseCholesky::solve_in_place(double* b, int nrhs, SolvePrecision precision) const {
  if (!m_impl->ok) throw SolverFailure("SparseCholesky::solve_in_place called without a successful factorisation");
  if (nrhs < 1 || nrhs > 3) throw InvalidArgument("SparseCholesky::solve_in_place: 1, 2 or 3 right-hand sides");
  if (m_impl->backend == CholeskyBackend::kCholmod) {
    m_impl->cholmod_solve_in_place(b, nrhs, precision);
    return;
  }
  if (!m_impl->extracted) m_impl->extract();
  switch (nrhs) {
    case 1: m_impl->simplicial.solve<1>(b); break;
    case 2: m_impl->simplicial.solve<2>(b); break;
    case 3: m_impl->simplicial.solve<3>(b); break;
    default: break;
  }
}

void SparseCholesky::set_solve_precision(SolvePrecision precision) {
  m_impl->precision = precision;
  if (m_impl->ok && m_impl->backend == CholeskyBackend::kCholmod) m_impl->copy_factor();
}

bool SparseCholesky::parallel_solve() const {
  return m_impl->backend == CholeskyBackend::kCholmod && m_impl->split.parallel();
}

bool SparseCholesky::reused_ordering() const { return m_impl->reused_ordering; }

std::string_view SparseCholesky::backend_name() const {
  return m_impl->backend == CholeskyBackend::kCholmod ? "cholmod" : "eigen-ldlt";
}

}  // namespace hooke
