// The method "auto" (calibrate::choose_method): picks from a measured table by element kind and nu, interpolating
// between tabulated nu; the library's table is the one the nu-range study writes (tests/experiments/test_nu_range.cpp
// reruns part of the study against it).
#include <gtest/gtest.h>

#include <hooke/calibrate/method_choice.hpp>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/core/error.hpp>
#include <hooke/mesh/generators.hpp>

namespace hooke::calibrate {
namespace {

using material::Law;
using material::Material;
using material::Plane;
using mesh::ElementKind;

Material at(double nu, Plane plane = Plane::kStress) { return Material{Law::kLinear, 14630.0, nu, plane, 1.0}; }

// Two methods whose worst cases cross between nu = 0.2 and 0.4: a at 0.1 / 0.3, b at 0.3 / 0.1 (they are equal at 0.3).
const std::vector<MeasuredError> kCrossing = {
    {"tet", 0.2, "a", 0.1, 6}, {"tet", 0.2, "b", 0.3, 6}, {"tet", 0.4, "a", 0.3, 6}, {"tet", 0.4, "b", 0.1, 6}};

TEST(MethodChoice, InterpolatesBetweenTabulatedNu) {
  EXPECT_EQ(choose_method(ElementKind::kTet, at(0.2), kCrossing).method, "a");
  EXPECT_EQ(choose_method(ElementKind::kTet, at(0.29), kCrossing).method, "a");
  EXPECT_EQ(choose_method(ElementKind::kTet, at(0.31), kCrossing).method, "b");
  EXPECT_EQ(choose_method(ElementKind::kTet, at(0.4), kCrossing).method, "b");
  const MethodChoice c = choose_method(ElementKind::kTet, at(0.25), kCrossing);
  EXPECT_NE(c.reason.find("interpolated between nu = 0.200 and 0.400"), std::string::npos) << c.reason;
  EXPECT_NE(c.reason.find(": 0.150; b 0.250"), std::string::npos) << c.reason;  // a quarter of the way
}

TEST(MethodChoice, OutsideTheTableTheNearestValueCounts) {
  EXPECT_EQ(choose_method(ElementKind::kTet, at(-0.5), kCrossing).method, "a");
  const MethodChoice c = choose_method(ElementKind::kTet, at(0.49), kCrossing);
  EXPECT_EQ(c.method, "b");
  EXPECT_NE(c.reason.find("outside the measured range"), std::string::npos) << c.reason;
}

// Equal errors: the method best at more of the tabulated nu (here b, which alone is best at 0.4).
TEST(MethodChoice, TiesGoToTheMethodBestAtMoreNu) {
  const std::vector<MeasuredError> t = {
      {"tet", 0.2, "a", 0.2, 6}, {"tet", 0.2, "b", 0.2, 6}, {"tet", 0.4, "a", 0.3, 6}, {"tet", 0.4, "b", 0.1, 6}};
  EXPECT_EQ(choose_method(ElementKind::kTet, at(0.2), t).method, "b");
}

TEST(MethodChoice, TablesAreKeptApart) {
  const std::vector<MeasuredError> t = {{"tet", 0.3, "a", 0.1, 6},
                                        {"triangle plane-stress", 0.3, "b", 0.1, 3},
                                        {"triangle plane-strain", 0.3, "c", 0.1, 3}};
  EXPECT_EQ(choose_method(ElementKind::kTet, at(0.3), t).method, "a");
  EXPECT_EQ(choose_method(ElementKind::kTriangle, at(0.3, Plane::kStress), t).method, "b");
  EXPECT_EQ(choose_method(ElementKind::kTriangle, at(0.3, Plane::kStrain), t).method, "c");
  EXPECT_THROW(choose_method(ElementKind::kTet, at(0.3), {{"triangle plane-stress", 0.3, "b", 0.1, 3}}),
               InvalidArgument);
}

TEST(MethodChoice, SurfacesAndQuadsHaveTheirOwnReason) {
  // A closed surface is tetrahedralized first: the tet table's pick, and the reason says so.
  EXPECT_EQ(choose_method(ElementKind::kSurfaceTriangle, at(0.3)).method,
            choose_method(ElementKind::kTet, at(0.3)).method);
  EXPECT_NE(choose_method(ElementKind::kSurfaceTriangle, at(0.3)).reason.find("tetrahedralize"), std::string::npos);
  EXPECT_EQ(choose_method(ElementKind::kQuad, at(0.3)).method, "stiffness-fit");
}

// The library's table: tets and both 2D reductions over the study's nu, and what it says at tissue nu.
TEST(MethodChoice, TheLibraryTableCoversEveryKindItNames) {
  for (const char* table : {"tet", "triangle plane-stress", "triangle plane-strain"}) {
    int n = 0;
    for (const MeasuredError& e : measured_errors())
      if (e.table == table) {
        ++n;
        EXPECT_GE(e.worst_relative_l2, 0.0);
        EXPECT_GT(e.cases, 0);
      }
    EXPECT_GE(n, 9) << table;
  }
  EXPECT_EQ(choose_method(ElementKind::kTet, at(0.45)).method, "stiffness-fit-volume");
}

// The factory resolves "auto": the model carries the chosen method and why, and equals a model calibrated by the
// chosen method's name.
TEST(MethodChoice, TheFactoryRecordsTheChoice) {
  const mesh::Mesh m = mesh::tet_box(0.02, 0.02, 0.04, 2, 2, 4);
  const CalibratedModel a = calibrate_model(m, at(0.45), {});
  EXPECT_EQ(a.method, choose_method(ElementKind::kTet, at(0.45)).method);
  EXPECT_EQ(a.choice, choose_method(ElementKind::kTet, at(0.45)).reason);
  ModelOptions named;
  named.method = a.method;
  const CalibratedModel b = calibrate_model(m, at(0.45), named);
  EXPECT_TRUE(b.choice.empty());
  ASSERT_EQ(a.springs.stiffness.size(), b.springs.stiffness.size());
  EXPECT_EQ((a.springs.stiffness - b.springs.stiffness).cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace hooke::calibrate
