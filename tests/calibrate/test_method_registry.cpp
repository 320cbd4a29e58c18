// The calibration methods' registry (calibrate/method_registry.hpp): one entry per Method, in its order, each with
// its equation and springs; the generic refusals and validity warnings read the entries.
#include <gtest/gtest.h>

#include <hooke/calibrate/method_registry.hpp>
#include <hooke/core/error.hpp>
#include <hooke/mesh/generators.hpp>

namespace hooke::calibrate {
namespace {

TEST(MethodRegistry, EveryMethodHasOneCompleteEntryInItsOrder) {
  const auto entries = method_registry();
  ASSERT_EQ(entries.size(), method_names().size());
  for (size_t k = 0; k < entries.size(); ++k) {
    EXPECT_EQ(static_cast<size_t>(entries[k].method), k);
    EXPECT_FALSE(entries[k].equation.empty()) << method_names()[k];
    EXPECT_NE(entries[k].takes, nullptr);
    EXPECT_NE(entries[k].springs, nullptr);
    EXPECT_EQ(method_equation(entries[k].method), entries[k].equation);
  }
}

TEST(MethodRegistry, RefusalsAndWarningsComeFromTheEntries) {
  const mesh::Mesh tets = mesh::tet_box(0.01, 0.01, 0.02, 1, 1, 2);
  const material::Material m{material::Law::kLinear, 1e4, 0.3};
  try {
    calibrate(tets, {m}, Method::kLloydSquare);
    FAIL() << "lloyd-square took tets";
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "method 'lloyd-square' needs quads, not a tet mesh");
  }
  const std::vector<std::string> w = validity_warnings(tets, {m}, Method::kLloydTet);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("lloyd-tet (Eq. 12) is derived for nu = 1/4, not 0.3"), std::string::npos) << w[0];
  EXPECT_TRUE(validity_warnings(tets, {m}, Method::kAnyNuTet).empty());  // exact at any nu
  const material::Material quarter{material::Law::kLinear, 1e4, 0.25};
  EXPECT_TRUE(validity_warnings(tets, {quarter}, Method::kLloydTet).empty());
}

}  // namespace
}  // namespace hooke::calibrate
