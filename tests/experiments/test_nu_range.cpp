// The nu-range study against the library's method table (calibrate::measured_errors): a reduced grid rerun here
// gives the table's numbers for the cases it covers, and the method the table picks.
#include <gtest/gtest.h>

#include <hooke/calibrate/method_choice.hpp>
#include <hooke/experiments/nu_range.hpp>

namespace hooke::experiments {
namespace {

const calibrate::MeasuredError* find(const std::vector<calibrate::MeasuredError>& t, const std::string& table,
                                     double nu, const std::string& method) {
  for (const auto& e : t)
    if (e.table == table && e.poisson == nu && e.method == method) return &e;
  return nullptr;
}

// Both tet meshes and the triangle mesh in plane strain at nu = 0.45, small strain only: the same cases the table's
// entries at 0.45 were taken over, so the same worst errors (to the solver's tolerance) and the same pick.
TEST(NuRange, AReducedGridReproducesTheLibraryTable) {
  NuRangeOptions o;
  o.poisson = {0.45};
  o.methods = {"lloyd-tet", "stiffness-fit-volume", "any-nu-tet"};
  o.triangle_methods = {"lloyd-triangle", "any-nu-triangle", "stiffness-fit"};
  o.planes = {"strain"};
  o.large_strain = 0.0;
  const NuRangeReport r = reproduce_nu_range(HOOKE_MESH_DATA, o);
  ASSERT_EQ(r.method_table.size(), 6u);
  for (const std::string table : {"tet", "triangle plane-strain"}) {
    std::string best;
    double best_error = 1e300;
    for (const auto& e : r.method_table) {
      if (e.table != table) continue;
      const calibrate::MeasuredError* lib = find(calibrate::measured_errors(), table, 0.45, e.method);
      ASSERT_NE(lib, nullptr) << table << " " << e.method;
      EXPECT_EQ(e.cases, lib->cases) << table << " " << e.method;
      EXPECT_NEAR(e.worst_relative_l2, lib->worst_relative_l2, 1e-6) << table << " " << e.method;
      if (e.worst_relative_l2 < best_error) best_error = e.worst_relative_l2, best = e.method;
    }
    material::Material m{material::Law::kLinear, 14630.0, 0.45};
    m.plane = table == "tet" ? material::Plane::kStress : material::Plane::kStrain;
    const mesh::ElementKind kind = table == "tet" ? mesh::ElementKind::kTet : mesh::ElementKind::kTriangle;
    EXPECT_EQ(calibrate::choose_method(kind, m).method, best) << table;
  }
}

}  // namespace
}  // namespace hooke::experiments
