// The nu-range study against the library's method table (calibrate::measured_errors): a reduced grid rerun here
// gives the table's numbers for the cases it covers, and the method the table picks.
#include <gtest/gtest.h>

#include <algorithm>
#include <hooke/core/error.hpp>

#include <hooke/calibrate/method_choice.hpp>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/experiments/compare.hpp>
#include <hooke/experiments/nu_range.hpp>
#include <hooke/experiments/term_law_fit.hpp>
#include <hooke/io/mesh_io.hpp>

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
  o.laws.clear();
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

// A law regime on the 87-node cylinder at nu = 0.45: per load a Hookean and a fitted row per method. Checked against
// the public paths: the Hookean row is `compare` under displacement control (a separate FEM and spring solve), the
// fitted row's exponents are fit_term_law's on the same model, and its worst case at the regime's strain is within the
// fit's worst case (which also covers half the strain). The rows survive JSON, and the regime gets its pick.
TEST(NuRange, ALawRegimeComparesHookeanAndFittedModelsUnderDisplacementControl) {
  NuRangeOptions o;
  o.poisson = {0.45};
  o.methods = {"any-nu-tet"};
  o.meshes = {"cylinder"};
  o.large_strain = 0.0;
  o.laws = {{"neohookean", 0.2}};
  o.fit_refinements = 1;
  const NuRangeReport r = reproduce_nu_range(HOOKE_MESH_DATA, o);
  std::vector<const NuRangeRow*> law_rows;
  for (const auto& row : r.rows)
    if (row.control == "displacement") law_rows.push_back(&row);
  ASSERT_EQ(law_rows.size(), 6u);  // three loads x (Hookean, fitted)

  const mesh::Mesh mesh = io::read_mesh(std::string(HOOKE_MESH_DATA) + "/cylinder.msh");
  const material::Material linear{material::Law::kLinear, 14630.0, 0.45};
  calibrate::ModelOptions mo;
  mo.method = "any-nu-tet";
  const calibrate::CalibratedModel model = calibrate::calibrate_model(mesh, linear, mo);
  TermLawFitOptions fo;
  fo.law = material::Law::kNeoHookean;
  fo.strain_range = 0.2;
  fo.refinements = 1;
  const TermLawFit fit = fit_term_law(model, fo);
  double fitted_worst = 0.0;
  for (const NuRangeRow* row : law_rows) {
    ASSERT_EQ(row->status, "converged") << row->load << " " << row->term_law;
    EXPECT_EQ(row->reference, "neohookean");
    EXPECT_EQ(row->strain, 0.2);
    if (row->term_law == "hookean") {
      EXPECT_EQ(row->spring_exponent, 1.0);
      CompareOptions co;
      co.load = model::load_kind_from_name(row->load);
      co.control = model::LoadControl::kDisplacement;
      co.strain = 0.2;
      co.reference = material::Law::kNeoHookean;
      const Comparison c = compare_calibrated(model, co);
      ASSERT_EQ(c.spring_report.status, solve::SolveStatus::kConverged);
      EXPECT_NEAR(row->relative_l2, c.relative_l2, 1e-6) << row->load;
      EXPECT_NEAR(row->force_error, c.reaction_error, 1e-6) << row->load;
    } else {
      ASSERT_EQ(row->term_law, "fitted");
      EXPECT_EQ(row->spring_exponent, fit.spring_exponent);
      EXPECT_EQ(row->volume_exponent, fit.volume_exponent);
      fitted_worst = std::max({fitted_worst, row->relative_l2, row->force_error});
    }
  }
  EXPECT_LE(fitted_worst, fit.worst_error + 1e-6);
  EXPECT_GT(fitted_worst, 0.0);

  const std::vector<NuRangeRow> back = nu_range_rows_from_json(nu_range_rows_json(r.rows));
  ASSERT_EQ(back.size(), r.rows.size());
  for (std::size_t i = 0; i < back.size(); ++i) {
    EXPECT_EQ(back[i].control, r.rows[i].control);
    EXPECT_EQ(back[i].term_law, r.rows[i].term_law);
    EXPECT_EQ(back[i].force_error, r.rows[i].force_error);
    EXPECT_EQ(back[i].volume_exponent, r.rows[i].volume_exponent);
  }
  const NuRangeOptions o2 = nu_range_options_from_json(nu_range_options_json(o));
  ASSERT_EQ(o2.laws.size(), 1u);
  EXPECT_EQ(o2.laws[0].law, "neohookean");
  EXPECT_EQ(o2.fit_refinements, 1);
  const auto pick = std::find_if(r.recommendations.begin(), r.recommendations.end(), [](const std::string& line) {
    return line.find("neohookean FEM at 20 % strain, displacement control: any-nu-tet") != std::string::npos;
  });
  EXPECT_NE(pick, r.recommendations.end());
}

TEST(NuRange, RefusesALawRegimeItCannotRun) {
  NuRangeOptions o;
  o.meshes = {"cylinder"};
  o.laws = {{"rubber", 0.2}};
  EXPECT_THROW(nu_range_tasks(HOOKE_MESH_DATA, o), InvalidArgument);
  o.laws = {{"neohookean", 0.7}};
  EXPECT_THROW(nu_range_tasks(HOOKE_MESH_DATA, o), InvalidArgument);
}

}  // namespace
}  // namespace hooke::experiments
