#pragma once
/// Order statistics of timing samples (benchmarks, the physics and haptic loops' statistics).
#include <vector>

namespace hooke {

/// The q-quantile of `values` by nearest rank (q = 0.5: the median), in their units; 0 for none. @pre 0 <= q <= 1
double quantile(std::vector<double> values, double q);

}  // namespace hooke
