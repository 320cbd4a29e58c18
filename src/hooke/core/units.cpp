#include <hooke/core/error.hpp>
#include <hooke/core/units.hpp>
#include <string>

namespace hooke {

double metres_per_unit(std::string_view unit) {
  if (unit == "m") return 1.0;
  if (unit == "cm") return 1e-2;
  if (unit == "mm") return 1e-3;
  if (unit == "um") return 1e-6;
  throw InvalidArgument("unknown length unit '" + std::string(unit) + "' (use m, cm, mm or um)");
}

}  // namespace hooke
