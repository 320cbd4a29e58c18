// Model files: calibrate -> write -> read gives the same model bit for bit, a hand-written file reads as written,
// and malformed files are rejected naming the entry.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/calibrate/model_file.hpp>
#include <hooke/core/error.hpp>
#include <hooke/mesh/generators.hpp>
#include <numeric>
#include <regex>
#include <sstream>

#include "support/meshes.hpp"

namespace hooke::calibrate {
namespace {

CalibratedModel tet_model(const std::string& method) {
  mesh::Mesh m = test::irregular_mesh(mesh::ElementKind::kTet, 3, 0.2);
  m.source = "irregular tet box";
  ModelOptions o;
  o.method = method;
  o.density = 1100.0;
  return calibrate_model(m, {material::Law::kLinear, 14630.0, 0.3}, o);
}

CalibratedModel surface_model() {
  ModelOptions o;
  o.method = "surface";
  return calibrate_model(mesh::uv_sphere_surface(6, 10, 0.05), {material::Law::kLinear, 1000.0, 0.3}, o);
}

// A cube's edges and corners are creases: their anchors carry a normal cone (11 entries per row).
CalibratedModel cube_surface_model() {
  ModelOptions o;
  o.method = "surface";
  return calibrate_model(mesh::cube_surface(3, 0.1), {material::Law::kLinear, 1000.0, 0.45}, o);
}

void expect_same(const CalibratedModel& a, const CalibratedModel& b) {
  EXPECT_EQ(a.method, b.method);
  EXPECT_EQ(a.equation, b.equation);
  EXPECT_EQ(a.mesh.kind, b.mesh.kind);
  EXPECT_TRUE(a.mesh.nodes == b.mesh.nodes);  // bit for bit
  EXPECT_TRUE(a.mesh.elements == b.mesh.elements);
  EXPECT_TRUE(a.masses == b.masses);
  EXPECT_EQ(a.springs.pairs, b.springs.pairs);
  EXPECT_TRUE(a.springs.stiffness == b.springs.stiffness);
  EXPECT_TRUE(a.springs.rest_length == b.springs.rest_length);
  EXPECT_TRUE(a.springs.volume_tets == b.springs.volume_tets);
  EXPECT_TRUE(a.springs.volume_stiffness == b.springs.volume_stiffness);
  EXPECT_TRUE(a.springs.rest_volume == b.springs.rest_volume);
  EXPECT_EQ(a.material.youngs_modulus, b.material.youngs_modulus);
  EXPECT_EQ(a.material.poisson_ratio, b.material.poisson_ratio);
  EXPECT_EQ(a.density, b.density);
  EXPECT_EQ(a.warnings, b.warnings);
  ASSERT_EQ(a.surface.has_value(), b.surface.has_value());
  if (a.surface) {
    EXPECT_TRUE(a.surface->normals == b.surface->normals);
    EXPECT_TRUE(a.surface->normal_cones == b.surface->normal_cones);
    EXPECT_TRUE(a.surface->k_normal == b.surface->k_normal);
    EXPECT_TRUE(a.surface->k_shear == b.surface->k_shear);
    EXPECT_TRUE(a.surface->k_bulk == b.surface->k_bulk);
    EXPECT_TRUE(a.surface->normal_length == b.surface->normal_length);
    EXPECT_EQ(a.surface->rest_volume, b.surface->rest_volume);
    EXPECT_EQ(a.surface->bulk_modulus, b.surface->bulk_modulus);
    EXPECT_EQ(a.surface->anchor_law, b.surface->anchor_law);
    EXPECT_TRUE(a.surface->centre == b.surface->centre);
  }
}

class ModelFileRoundTrip : public testing::TestWithParam<std::string> {};

TEST_P(ModelFileRoundTrip, WriteReadIsBitForBit) {
  const CalibratedModel a = GetParam() == "surface"        ? surface_model()
                            : GetParam() == "surface-cube" ? cube_surface_model()
                                                           : tet_model(GetParam());
  const CalibratedModel b = parse_model(model_json(a), "round trip");
  expect_same(a, b);
  // and the model built from the file has the same forces as the one built from the calibration
  const auto ma = build_model(a).model, mb = build_model(b).model;
  VecX x = ma->rest_positions() + 1e-3 * VecX::Random(ma->dof_count());
  EXPECT_TRUE(ma->gradient(x) == mb->gradient(x));
}

INSTANTIATE_TEST_SUITE_P(Methods, ModelFileRoundTrip,
                         testing::Values("lloyd-tet", "lloyd-tet-volume", "stiffness-fit", "any-nu-tet", "surface",
                                         "surface-cube"));

TEST(ModelFile, AnchorRowsHaveANormalAndOptionallyACone) {
  const std::string text = model_json(cube_surface_model());
  // the smooth face centres write 5 entries, the crease nodes 11
  EXPECT_NE(text.find("\"anchors\""), std::string::npos);
  const std::regex eleven(R"(\n      \[[^\]\n]*(, [^\],\n]+){10}\])");
  EXPECT_TRUE(std::regex_search(text, eleven));
  // a row of another length is refused naming it
  const std::string bad = std::regex_replace(text, std::regex(R"(("anchors": \[\n      \[[^,]+),)"), "$1, 1.0,",
                                             std::regex_constants::format_first_only);
  ASSERT_NE(bad, text);
  try {
    parse_model(bad, "bad.json");
    ADD_FAILURE() << "a 6- or 12-entry anchor row was read";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("surface.anchors[0]"), std::string::npos) << e.what();
  }
}

TEST(ModelFile, CertificateAndWarningsRoundTrip) {
  CalibratedModel a = tet_model("lloyd-tet");
  ASSERT_FALSE(a.warnings.empty());  // nu = 0.3 is not lloyd-tet's 1/4
  a.certificate = {{"stretch", 0.01, 1.5e-4, 3.25e-5, 0.123456789012345}};
  const CalibratedModel b = parse_model(model_json(a), "round trip");
  ASSERT_EQ(b.certificate.size(), 1u);
  EXPECT_EQ(b.certificate[0].relative_l2, 0.123456789012345);
  EXPECT_EQ(b.certificate[0].load, "stretch");
}

TEST(ModelFile, SurfaceModelBuiltFromDataHasTheForcesOfTheSurfaceModel) {
  const mesh::Mesh sphere = mesh::uv_sphere_surface(6, 10, 0.05);
  const material::Material mat{material::Law::kLinear, 1000.0, 0.3};
  const SurfaceModel direct = make_surface_model(sphere, mat, {});
  const BuiltModel built = build_model(surface_model());
  ASSERT_NE(built.volume_penalty, nullptr);
  const VecX x = direct.model->rest_positions() + 2e-3 * VecX::Random(direct.model->dof_count());
  EXPECT_LT((direct.model->gradient(x) - built.model->gradient(x)).norm(), 1e-12 * direct.model->gradient(x).norm());
}

TEST(ModelFile, HandWrittenFileReadsAsWritten) {
  const CalibratedModel m = read_model(std::string(HOOKE_TEST_DATA) + "/models/hand_written_square.json");
  EXPECT_EQ(m.method, "hand-tuned");
  EXPECT_EQ(m.mesh.kind, mesh::ElementKind::kTriangle);
  ASSERT_EQ(m.mesh.node_count(), 4);
  ASSERT_EQ(m.springs.pairs.size(), 5u);
  EXPECT_EQ(m.springs.pairs[4], (std::array<int, 2>{0, 2}));  // written as [2, 0]
  EXPECT_EQ(m.springs.stiffness(4), 50.0);
  EXPECT_EQ(m.masses(2), 2e-5);  // node 1, x
  EXPECT_EQ(m.masses(3), 2e-5);  // node 1, y
  EXPECT_EQ(m.material.thickness, 0.001);
  // Forces from the file's numbers, derived by hand: only the diagonal (l = sqrt(2) cm, l0 = 1.2 cm) is stretched
  // at rest; dE/dp_0 = k (l - l0) (p_0 - p_2) / l.
  const auto model = build_model(m).model;
  const VecX g = model->gradient(model->rest_positions());
  const double l = 0.01 * std::sqrt(2.0), k = 50.0, l0 = 0.012;
  EXPECT_NEAR(g(0), k * (l - l0) * (-0.01) / l, 1e-15);
  EXPECT_NEAR(g(1), k * (l - l0) * (-0.01) / l, 1e-15);
  EXPECT_NEAR(g(2), 0.0, 1e-15);
}

// A valid file with one defect; the error must name the entry.
struct Defect {
  const char* name;
  const char* pattern;      // regex on the valid text
  const char* replacement;  // first match replaced
  const char* entry;        // expected in the message
};

class MalformedModelFile : public testing::TestWithParam<Defect> {};

TEST_P(MalformedModelFile, IsRejectedNamingTheEntry) {
  std::ifstream in(std::string(HOOKE_TEST_DATA) + "/models/hand_written_square.json");
  std::stringstream text;
  text << in.rdbuf();
  const std::string bad = std::regex_replace(text.str(), std::regex(GetParam().pattern), GetParam().replacement,
                                             std::regex_constants::format_first_only);
  ASSERT_NE(bad, text.str()) << "the defect was not applied";
  try {
    parse_model(bad, "bad.json");
    FAIL() << "accepted a file with " << GetParam().name;
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "bad.json");
    EXPECT_NE(std::string(e.what()).find(GetParam().entry), std::string::npos) << e.what();
  } catch (const InvalidMesh& e) {
    EXPECT_NE(std::string(e.what()).find(GetParam().entry), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Defects, MalformedModelFile,
    testing::Values(
        Defect{"an index out of range", R"(\[1, 2, 100, 0\.01\])", "[1, 9, 100, 0.01]", "springs[1]"},
        Defect{"a negative stiffness", R"(\[2, 3, 100,)", "[2, 3, -100,", "springs[2]"},
        Defect{"a zero rest length", R"(\[0, 3, 100, 0\.01\])", "[0, 3, 100, 0]", "springs[3]"},
        Defect{"a NaN (as a string)", R"(\[0, 1, 100,)", "[0, 1, \"NaN\",", "springs[0]"},
        Defect{"a wrong schema version", R"("schema_version": 1)", "\"schema_version\": 2", "schema_version"},
        Defect{"too few masses", R"(, 2e-5\],)", "],", "masses"},
        Defect{"a spring of one node", R"(\[2, 3, 100,)", "[3, 3, 100,", "springs[2]"},
        Defect{"a fractional index", R"(\[0, 1, 100,)", "[0, 1.5, 100,", "springs[0]"},
        Defect{"a misspelt key", R"("springs")", "\"sprngs\"", "sprngs"},
        Defect{"a negative mass", R"("masses": \[1e-5)", "\"masses\": [-1e-5", "masses[0]"},
        Defect{"an element index out of range", R"(\[0, 2, 3\])", "[0, 2, 4]", "elements[1]"},
        Defect{"an inverted element", R"(\[0, 2, 3\])", "[0, 3, 2]", "triangle 1"},
        Defect{"non-SI units", R"("method")", "\"units\": {\"length\": \"mm\"}, \"method\"", "units.length"},
        Defect{"broken JSON syntax", R"(\[0, 1, 100, 0\.01\],)", "[0, 1, 100, 0.01],,", ":13:"},
        Defect{"a missing material key", R"("youngs_modulus": 1000, )", "", "material"},
        Defect{"an invalid material", R"("poisson_ratio": 0\.3)", "\"poisson_ratio\": 0.5", "material"}),
    [](const testing::TestParamInfo<Defect>& p) {
      std::string s = p.param.name;
      for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return s;
    });

TEST(ModelFile, ExportsWriteSpringsForParaViewAndSpreadsheets) {
  const CalibratedModel m = tet_model("lloyd-tet");
  const auto dir = std::filesystem::temp_directory_path() / "hooke_model_exports";
  std::filesystem::create_directories(dir);
  write_model(dir / "m.csv", m);
  write_model(dir / "m.vtu", m);
  std::ifstream csv(dir / "m.csv");
  std::string header, first;
  std::getline(csv, header);
  std::getline(csv, first);
  EXPECT_EQ(header, "i,j,stiffness_n_per_m,rest_length_m");
  long lines = 2;
  for (std::string l; std::getline(csv, l);) ++lines;
  EXPECT_EQ(lines, static_cast<long>(m.springs.pairs.size()) + 1);
  std::ifstream vtu(dir / "m.vtu");
  std::stringstream text;
  text << vtu.rdbuf();
  EXPECT_NE(text.str().find("Name=\"stiffness\""), std::string::npos);
  EXPECT_NE(text.str().find("NumberOfCells=\"" + std::to_string(m.springs.pairs.size()) + "\""), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir / "m_elements.vtu"));
  EXPECT_THROW(write_model(dir / "m.txt", m), InvalidArgument);
  std::filesystem::remove_all(dir);
}

TEST(ModelFile, RequireSameNodesRejectsAnotherMesh) {
  const CalibratedModel m = tet_model("lloyd-tet");
  EXPECT_NO_THROW(require_same_nodes(m, m.mesh));
  mesh::Mesh other = m.mesh;
  other.nodes(3, 0) += 1e-3;
  EXPECT_THROW(require_same_nodes(m, other), InvalidArgument);
  EXPECT_THROW(require_same_nodes(m, mesh::tet_box(0.01, 0.01, 0.01, 1, 1, 1)), InvalidArgument);
}

TEST(ModelFactory, RejectsUnknownMethodsListingTheNames) {
  try {
    tet_model("lloyd-cube");
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("surface"), std::string::npos);
  }
}

TEST(ModelFactory, PermutedModelHasPermutedForces) {
  const CalibratedModel m = tet_model("lloyd-tet-volume");
  const int n = m.mesh.node_count();
  std::vector<int> new_to_old(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) new_to_old[static_cast<size_t>(k)] = (7 * k + 3) % n;
  ASSERT_EQ(std::gcd(7, n), 1);
  const CalibratedModel p = permute_nodes(m, new_to_old);
  const auto a = build_model(m).model, b = build_model(p).model;
  const VecX x = a->rest_positions() + 1e-3 * VecX::Random(a->dof_count());
  VecX y(x.size());
  for (int k = 0; k < n; ++k) y.segment<3>(3 * k) = x.segment<3>(3 * new_to_old[static_cast<size_t>(k)]);
  const VecX ga = a->gradient(x), gb = b->gradient(y);
  for (int k = 0; k < n; ++k)
    EXPECT_LT((gb.segment<3>(3 * k) - ga.segment<3>(3 * new_to_old[static_cast<size_t>(k)])).norm(), 1e-12 * ga.norm());
}

}  // namespace
}  // namespace hooke::calibrate
