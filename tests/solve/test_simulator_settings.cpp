// solve::simulator_fields: the integrator's settings by name, as the CLI, scripts and Python set them.
#include <gtest/gtest.h>

#include <hooke/core/error.hpp>
#include <hooke/solve/simulator_settings.hpp>
#include <set>

namespace hooke::solve {
namespace {

bool same(const SimulatorOptions& a, const SimulatorOptions& b) {
  for (const SimulatorField& f : simulator_fields())
    if (f.get(a) != f.get(b)) return false;
  return true;
}

TEST(SimulatorFields, NamesAreDistinctAndEveryValueRoundTrips) {
  std::set<std::string_view> names;
  const SimulatorOptions defaults;
  for (const SimulatorField& f : simulator_fields()) {
    EXPECT_TRUE(names.insert(f.name).second) << f.name;
    EXPECT_FALSE(f.help.empty()) << f.name;
    SimulatorOptions o;
    f.set(o, f.get(defaults));  // the default shown in --help is taken back unchanged
    EXPECT_TRUE(same(o, defaults)) << f.name;
  }
}

TEST(SimulatorFields, EachNameSetsItsOwnField) {
  const std::pair<const char*, const char*> values[] = {{"integrator", "implicit-euler"}, {"qn-iterations", "20"},
                                                        {"qn-tolerance", "0.001"},        {"qn-hessian", "isotropic"},
                                                        {"linear-solver", "cg"},          {"cg-tolerance", "1e-08"},
                                                        {"newton-tolerance", "1e-07"},    {"newton-iterations", "7"},
                                                        {"global-solve", "chebyshev"},    {"iterations", "4"}};
  ASSERT_EQ(std::size(values), simulator_fields().size());
  for (const auto& [name, text] : values) {
    SimulatorOptions o;
    ASSERT_TRUE(set_simulator_field(o, name, text)) << name;
    for (const SimulatorField& f : simulator_fields())
      EXPECT_EQ(f.get(o) == text, f.name == name) << name << " moved " << f.name;
  }
  SimulatorOptions o;
  set_simulator_field(o, "qn-iterations", "20");
  set_simulator_field(o, "cg-tolerance", "1e-08");
  set_simulator_field(o, "integrator", "local-global");
  EXPECT_EQ(o.quasi_newton.max_iterations, 20);
  EXPECT_EQ(o.newton.cg_tolerance, 1e-8);
  EXPECT_EQ(o.integrator, Integrator::kLocalGlobal);
}

TEST(SimulatorFields, UnknownNamesAndMalformedValues) {
  SimulatorOptions o;
  EXPECT_FALSE(set_simulator_field(o, "qn_iterations", "8"));  // dashes, not underscores
  EXPECT_THROW(set_simulator_field(o, "qn-iterations", "8.5"), InvalidArgument);
  EXPECT_THROW(set_simulator_field(o, "qn-iterations", "many"), InvalidArgument);
  EXPECT_THROW(set_simulator_field(o, "cg-tolerance", "nan"), InvalidArgument);
  EXPECT_THROW(set_simulator_field(o, "integrator", "euler"), InvalidArgument);
  EXPECT_TRUE(same(o, SimulatorOptions{}));  // nothing set by a refused value
}

}  // namespace
}  // namespace hooke::solve
