#pragma once
// The Seth-Hill strain of a stretch ratio and the energy g = e^2 / 2 built on it, with its first two derivatives: the
// one scalar law behind the large-strain springs (ratio l / l0) and volume terms (ratio V / V0), docs/methods/
// large_strain.md. e_q(r) = (r^q - 1) / q, e_0(r) = ln r. Every q has g(1) = g'(1) = 0 and g''(1) = 1: the law
// changes only what happens away from the rest state. q = 1 is the Hookean spring and the quadratic volume term.
#include <cmath>
#include <limits>

namespace hooke::springs::detail {

struct SethHillEnergy {
  double value = 0.0;   // g(r)
  double first = 0.0;   // g'(r)
  double second = 0.0;  // g''(r)
};

// r^n for an integer n by repeated squaring.
[[gnu::always_inline]] inline double integer_power(double r, int n) {
  double result = 1.0, base = n < 0 ? 1.0 / r : r;
  for (unsigned k = static_cast<unsigned>(n < 0 ? -n : n); k; k >>= 1, base *= base)
    if (k & 1u) result *= base;
  return result;
}

// r^q, r > 0. The fitted laws' exponents are multiples of 1/8 (experiments::fit_term_law): for those, square roots
// and products, a third of std::pow's time in the force loops; any other exponent by std::pow.
[[gnu::always_inline]] inline double ratio_power(double r, double q) {
  const double eighths = 8.0 * q;
  if (eighths != std::nearbyint(eighths) || std::abs(eighths) > 64.0) return std::pow(r, q);
  int n = static_cast<int>(eighths), root = 8;
  double base = r;
  while (root > 1 && n % 2 == 0) {  // reduce n / root
    n /= 2;
    root /= 2;
  }
  for (int k = root; k > 1; k /= 2) base = std::sqrt(base);
  return integer_power(base, n);
}

// g and its derivatives at ratio r for exponent q. r <= 0 (an inverted or collapsed element) has g = +infinity for
// q <= 0 (the law's barrier) and is inadmissible for every q != 1: value +infinity, derivatives 0.
[[gnu::always_inline]] inline SethHillEnergy seth_hill_energy(double r, double q) {
  if (q == 1.0) return {0.5 * (r - 1.0) * (r - 1.0), r - 1.0, 1.0};
  if (!(r > 0.0)) return {std::numeric_limits<double>::infinity(), 0.0, 0.0};
  const double rq = q == 0.0 ? 1.0 : ratio_power(r, q);
  const double e = q == 0.0 ? std::log(r) : (rq - 1.0) / q;
  const double de = rq / r;               // r^(q - 1)
  const double d2e = (q - 1.0) * de / r;  // (q - 1) r^(q - 2)
  return {0.5 * e * e, e * de, de * de + e * d2e};
}

}  // namespace hooke::springs::detail
