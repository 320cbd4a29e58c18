#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/io/field.hpp>

namespace hooke::io {

void require_finite(const Field& field, const std::filesystem::path& file) {
  for (Eigen::Index q = 0; q < field.values.size(); ++q)
    if (!std::isfinite(field.values(q)))
      throw NonFiniteResult("'" + field.name + "' of entity " + std::to_string(q / std::max(field.components, 1)) +
                            " is " + std::to_string(field.values(q)) + " (the result overflowed); " + file.string() +
                            " was not written");
}

void require_finite_positions(const RowMatX& nodes, const std::filesystem::path& file) {
  for (Eigen::Index i = 0; i < nodes.rows(); ++i)
    if (!nodes.row(i).allFinite())
      throw NonFiniteResult("the position of node " + std::to_string(i) + " is not finite (the result overflowed); " +
                            file.string() + " was not written");
}

}  // namespace hooke::io
