// The one dynamics setup that `hooke simulate`, the viewer and Python's live simulation share: its range checks
// and the solver's Dynamics it makes.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <hooke/core/error.hpp>
#include <hooke/solve/dynamics_setup.hpp>
#include <set>
#include <string_view>

namespace hooke::solve {
namespace {

TEST(DynamicsSetup, RefusesOutOfRangeFields) {
  EXPECT_NO_THROW(validate(DynamicsSetup{}));
  const std::function<void(DynamicsSetup&)> bad[] = {
      [](DynamicsSetup& s) { s.dt = 0.0; },
      [](DynamicsSetup& s) { s.dt = -1e-3; },
      [](DynamicsSetup& s) { s.dt = std::nan(""); },
      [](DynamicsSetup& s) { s.dt = INFINITY; },
      [](DynamicsSetup& s) { s.damping_mass = -1.0; },
      [](DynamicsSetup& s) { s.damping_stiffness = std::nan(""); },
      [](DynamicsSetup& s) { s.influence_radius = -0.1; },
      [](DynamicsSetup& s) { s.influence_radius = INFINITY; },
  };
  for (const auto& change : bad) {
    DynamicsSetup s;
    change(s);
    EXPECT_THROW(validate(s), InvalidArgument);
  }
}

TEST(DynamicsSetup, MakesGravityAlongTheVerticalAxisAndRayleighDamping) {
  DynamicsSetup s;
  s.damping_mass = 2.0;
  s.damping_stiffness = 3e-3;
  const VecX mass = VecX::Constant(6, 0.5);
  const Dynamics still = make_dynamics(s, mass, 3);
  EXPECT_EQ(still.gravity.size(), 0);
  EXPECT_EQ(still.mass, mass);
  EXPECT_EQ(still.mass_damping, 2.0);
  EXPECT_EQ(still.stiffness_damping, 3e-3);
  s.gravity = true;
  EXPECT_EQ(make_dynamics(s, mass, 3).gravity, Vec3(0.0, 0.0, -9.81));
  EXPECT_EQ(make_dynamics(s, VecX::Constant(4, 1.0), 2).gravity, Eigen::Vector2d(0.0, -9.81));
}

TEST(DynamicsSetup, TheRadiusOfInfluenceDefaultsToHalfTheDiagonal) {
  DynamicsSetup s;
  EXPECT_EQ(influence_radius(s, 3.0), 1.5);
  s.influence_radius = 0.2;
  EXPECT_EQ(influence_radius(s, 3.0), 0.2);
}

// The one name table behind --NAME, `set NAME VALUE` and Python's NAME=VALUE: every field settable by its name.
TEST(DynamicsSetup, EveryFieldIsSetByItsName) {
  std::set<std::string_view> names;
  for (const DynamicsField& f : dynamics_fields()) {
    EXPECT_TRUE(names.insert(f.name).second) << f.name;
    EXPECT_NE(f.number == nullptr, f.flag == nullptr) << f.name << ": a number or a flag";
    DynamicsSetup s;
    EXPECT_TRUE(set_dynamics_field(s, f.name, f.number ? "0.25" : "on")) << f.name;
    EXPECT_NE(s, DynamicsSetup{}) << f.name << " did not change the setup";
    if (f.number) {
      EXPECT_EQ(s.*f.number, 0.25);
    }
    EXPECT_THROW(set_dynamics_field(s, f.name, f.number ? "0.25x" : "yes"), InvalidArgument) << f.name;
  }
  EXPECT_EQ(names.size(), 5u);
  DynamicsSetup s;
  EXPECT_FALSE(set_dynamics_field(s, "young", "1e5"));
  EXPECT_THROW(set_dynamics_field(s, "dt", "nan"), InvalidArgument);
  EXPECT_TRUE(set_dynamics_field(s, "gravity", "on"));
  EXPECT_TRUE(set_dynamics_field(s, "gravity", "off"));
  EXPECT_FALSE(s.gravity);
}

}  // namespace
}  // namespace hooke::solve
