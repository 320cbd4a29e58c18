#pragma once
/// Stable names of an enum's values, both ways, with the error a user sees for an unknown name.
#include <array>
#include <hooke/core/error.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hooke {

template <typename Enum, std::size_t N>
struct NameTable {
  std::string_view what;  ///< what the names name, for the error ("anchor law")
  std::array<std::pair<Enum, std::string_view>, N> entries;

  /// The name of `value`, or "unknown" for a value outside the table.
  std::string_view name(Enum value) const {
    for (const auto& [e, n] : entries)
      if (e == value) return n;
    return "unknown";
  }
  /// Every name, in the table's order.
  std::vector<std::string_view> names() const {
    std::vector<std::string_view> out;
    for (const auto& [e, n] : entries) out.push_back(n);
    return out;
  }
  /// The value named `name`. @throws InvalidArgument listing the valid names
  Enum from_name(std::string_view name) const {
    std::string valid;
    for (const auto& [e, n] : entries) {
      if (n == name) return e;
      valid += (valid.empty() ? "" : ", ") + std::string(n);
    }
    throw InvalidArgument("unknown " + std::string(what) + " '" + std::string(name) + "' (use " + valid + ")");
  }
};

}  // namespace hooke
