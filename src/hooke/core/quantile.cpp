#include <algorithm>
#include <cmath>
#include <hooke/core/quantile.hpp>

namespace hooke {

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[static_cast<size_t>(q * static_cast<double>(v.size() - 1) + 0.5)];
}

}  // namespace hooke
