#pragma once
/// Length units accepted on input; everything inside is in metres.
#include <string_view>

namespace hooke {

/// Metres per unit for "m", "cm", "mm", "um". @throws InvalidArgument for any other name
double metres_per_unit(std::string_view unit);

}  // namespace hooke
