// Materials by region (calibrate/region_materials.hpp): parsing and mapping, a model of two equal tissues equal to
// the one-material model, and a box with a stiffer nodule against the two-material FEM of the same regions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/calibrate/model_file.hpp>
#include <hooke/calibrate/region_materials.hpp>
#include <hooke/core/error.hpp>
#include <hooke/experiments/certify.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/mesh/generators.hpp>
#include <iostream>

namespace hooke::calibrate {
namespace {

// A 2 cm cube of 6^3 x 6 tets with a nodule: region 2 is the tets whose centroid lies within 6 mm of a point 2 mm
// above the centre (a voxel-like, staircase interface), region 1 the rest.
mesh::Mesh nodule_box() {
  mesh::Mesh m = mesh::tet_box(0.02, 0.02, 0.02, 6, 6, 6);
  m.source = "nodule box";
  const Vec3 centre(0.01, 0.01, 0.012);
  for (int e = 0; e < m.element_count(); ++e) {
    Vec3 c = Vec3::Zero();
    for (int k = 0; k < 4; ++k) c += m.nodes.row(m.elements(e, k)).transpose() / 4.0;
    m.region(e) = (c - centre).norm() < 0.006 ? 2 : 1;
  }
  return m;
}

ModelOptions region_method(const std::string& name, std::vector<RegionMaterial> regions = {}) {
  ModelOptions o;
  o.method = name;
  o.regions = std::move(regions);
  return o;
}

double worst_l2(const std::vector<CertificateCase>& cases) {
  double w = 0.0;
  for (const CertificateCase& c : cases) w = std::max(w, c.relative_l2);
  return w;
}

TEST(RegionMaterials, ParsesAndRefuses) {
  EXPECT_EQ(parse_region_material("2=25000,0.45"), (RegionMaterial{2, 25000.0, 0.45}));
  EXPECT_EQ(parse_region_material("-1=1e4,0"), (RegionMaterial{-1, 1e4, 0.0}));
  for (const char* bad : {"2:25000,0.45", "2=25000", "x=1,0.3", "2=abc,0.3", "2=1e4,0.3x", "2=,0.3", "=1,0.3"})
    EXPECT_THROW(parse_region_material(bad), InvalidArgument) << bad;
  for (const char* bad : {"2=0,0.3", "2=-5,0.3", "2=1e4,0.5", "2=1e4,-1", "2=inf,0.3"})
    EXPECT_THROW(parse_region_material(bad), Error) << bad;
  EXPECT_THROW(validate_regions({{1, 1e4, 0.3}, {1, 2e4, 0.3}}), InvalidArgument);  // region 1 twice
}

TEST(RegionMaterials, MapsEachElementToItsRegionsMaterial) {
  const mesh::Mesh m = nodule_box();
  const material::Material base{material::Law::kLinear, 5000.0, 0.45};
  const auto one = element_materials(m, base, {});
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0], base);
  const auto mats = element_materials(m, base, {{2, 25000.0, 0.4}});
  ASSERT_EQ(mats.size(), static_cast<size_t>(m.element_count()));
  int nodule = 0;
  for (int e = 0; e < m.element_count(); ++e) {
    const material::Material& x = mats[static_cast<size_t>(e)];
    EXPECT_EQ(x.youngs_modulus, m.region(e) == 2 ? 25000.0 : 5000.0);
    EXPECT_EQ(x.poisson_ratio, m.region(e) == 2 ? 0.4 : 0.45);
    nodule += m.region(e) == 2;
  }
  EXPECT_GT(nodule, 100);
  EXPECT_LT(nodule, m.element_count() / 3);
  // a region the mesh lacks is named with the ones it has; require_all names the region left without material
  try {
    element_materials(m, base, {{3, 1e4, 0.3}});
    ADD_FAILURE() << "region 3 accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("region 3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("1 ("), std::string::npos) << e.what();
  }
  EXPECT_THROW(element_materials(m, base, {{2, 1e4, 0.3}}, true), InvalidArgument);
  EXPECT_NO_THROW(element_materials(m, base, {{2, 1e4, 0.3}, {1, 2e4, 0.3}}, true));
  // the rest's E and nu: as given, or (neither given) the first region's when every element is listed
  EXPECT_EQ(unlisted_elasticity(m, {{2, 1e4, 0.3}}, 5000.0, 0.45), std::make_pair(5000.0, 0.45));
  EXPECT_EQ(unlisted_elasticity(m, {{1, 2e4, 0.3}, {2, 1e4, 0.3}}, std::nan(""), std::nan("")),
            std::make_pair(2e4, 0.3));
  EXPECT_THROW(unlisted_elasticity(m, {{2, 1e4, 0.3}}, std::nan(""), std::nan("")), InvalidArgument);
  EXPECT_THROW(unlisted_elasticity(m, {{2, 1e4, 0.3}}, 5000.0, std::nan("")), InvalidArgument);
  EXPECT_THROW(unlisted_elasticity(m, {}, std::nan(""), std::nan("")), InvalidArgument);
}

// Two regions of the same material make exactly the one-material model, for every method that builds terms element
// by element (and stiffness-fit's global scale, fitted to the FEM of the same materials).
TEST(RegionMaterials, TwoEqualTissuesAreTheOneMaterialModel) {
  const mesh::Mesh m = nodule_box();
  const material::Material mat{material::Law::kLinear, 5000.0, 0.45};
  for (const char* name : {"lloyd-tet", "any-nu-tet", "stiffness-fit-volume"}) {
    const CalibratedModel one = calibrate_model(m, mat, region_method(name));
    const CalibratedModel two = calibrate_model(m, mat, region_method(name, {{1, 5000.0, 0.45}, {2, 5000.0, 0.45}}));
    ASSERT_EQ(one.springs.pairs, two.springs.pairs) << name;
    EXPECT_LT((one.springs.stiffness - two.springs.stiffness).cwiseAbs().maxCoeff(),
              1e-12 * one.springs.stiffness.maxCoeff())
        << name;
    ASSERT_EQ(one.springs.volume_stiffness.size(), two.springs.volume_stiffness.size()) << name;
    if (one.springs.volume_stiffness.size() > 0) {
      EXPECT_LT((one.springs.volume_stiffness - two.springs.volume_stiffness).cwiseAbs().maxCoeff(),
                1e-12 * one.springs.volume_stiffness.maxCoeff())
          << name;
    }
  }
}

// Lloyd's tet springs (Eq. 12-13) are linear in each element's E: a spring's k is a E_1 + b E_2, with a and b the
// summed contributions of its tets in each region. Two calibrations give a and b; a third at another E_2 is
// predicted. Springs inside the nodule carry b only, outside a only, on the interface both.
TEST(RegionMaterials, SpringsSumTheirTetsContributionsFromEachTissue) {
  const mesh::Mesh m = nodule_box();
  const material::Material mat{material::Law::kLinear, 5000.0, 0.25};
  auto k = [&](double e2) {
    return calibrate_model(m, mat, region_method("lloyd-tet", {{2, e2, 0.25}})).springs.stiffness;
  };
  const VecX k1 = k(5000.0), k2 = k(10000.0), k5 = k(25000.0);
  const VecX b = (k2 - k1) / 5000.0, a = (k1 - 5000.0 * b) / 5000.0;
  EXPECT_LT((k5 - (5000.0 * a + 25000.0 * b)).cwiseAbs().maxCoeff(), 1e-9 * k5.maxCoeff());
  int inside = 0, outside = 0, interface = 0;
  for (Eigen::Index s = 0; s < a.size(); ++s) {
    const bool has_a = a(s) > 1e-12 * a.maxCoeff(), has_b = b(s) > 1e-12 * b.maxCoeff();
    EXPECT_TRUE(has_a || has_b);
    EXPECT_GE(a(s), -1e-12 * a.maxCoeff());
    EXPECT_GE(b(s), -1e-12 * b.maxCoeff());
    inside += !has_a && has_b;
    outside += has_a && !has_b;
    interface += has_a && has_b;
  }
  EXPECT_GT(inside, 50);
  EXPECT_GT(outside, 500);
  EXPECT_GT(interface, 50);
}

// A nodule 5 times stiffer in the holed Gmsh cylinder (990 nodes): the two-material model against the two-material FEM
// is about as close as the one-material model is to its FEM (measured 0.098 against 0.090 for stiffness-fit-volume,
// 0.073 against 0.066 for any-nu-tet, worst of the three cases), while springs calibrated for the soft tissue alone
// are 0.21 off. (On the structured generators' meshes every spring model is 0.3-0.8 off at nu = 0.45 even with one
// material, so they cannot show this.)
TEST(RegionMaterials, ANoduleModelMatchesTheTwoMaterialFem) {
  mesh::Mesh m = io::read_mesh(HOOKE_MESH_DATA "/cylinder_hole.msh");
  const Vec3 centre(0.0, 0.0, 0.012);  // a ring of radius 6 mm around the hole, 2 mm above the middle
  for (int e = 0; e < m.element_count(); ++e) {
    Vec3 c = Vec3::Zero();
    for (int k = 0; k < 4; ++k) c += m.nodes.row(m.elements(e, k)).transpose() / 4.0;
    m.region(e) = (c - centre).norm() < 0.006 ? 2 : 1;
  }
  const material::Material soft{material::Law::kLinear, 5000.0, 0.45};
  const std::vector<RegionMaterial> nodule{{2, 25000.0, 0.45}};
  for (const char* name : {"stiffness-fit-volume", "any-nu-tet"}) {
    const double one = worst_l2(experiments::certify(calibrate_model(m, soft, region_method(name))));
    const double two = worst_l2(experiments::certify(calibrate_model(m, soft, region_method(name, nodule))));
    CalibratedModel blind = calibrate_model(m, soft, region_method(name));  // springs of the soft tissue alone ...
    blind.regions = nodule;                                                 // ... against the FEM with the nodule
    const double ignored = worst_l2(experiments::certify(blind));
    std::cout << name << ": worst relative L2, one material " << one << ", two materials " << two << ", nodule ignored "
              << ignored << "\n";
    EXPECT_LE(two, 0.10) << name;
    EXPECT_LE(two, 1.25 * one) << name;
    EXPECT_GT(ignored, 1.5 * two) << name;
  }
}

TEST(RegionMaterials, AModelFileKeepsTheRegions) {
  const mesh::Mesh m = nodule_box();
  const CalibratedModel model =
      calibrate_model(m, {material::Law::kLinear, 5000.0, 0.45}, region_method("any-nu-tet", {{2, 25000.0, 0.4}}));
  const auto path = std::filesystem::temp_directory_path() / "hooke_regions_model.json";
  write_model(path, model);
  const CalibratedModel back = read_model(path);
  std::filesystem::remove(path);
  EXPECT_EQ(back.regions, model.regions);
  EXPECT_EQ(back.mesh.region, m.region);
  EXPECT_EQ(element_materials(back), element_materials(model));
  // a region the elements do not have is refused, naming the entry
  CalibratedModel wrong = model;
  wrong.regions = {{7, 1e4, 0.3}};
  EXPECT_THROW(validate_model(wrong, "test"), InvalidArgument);
}

TEST(RegionMaterials, TheSurfaceModelHasOneMaterial) {
  const mesh::Mesh cube = mesh::cube_surface(4, 0.02);
  EXPECT_THROW(calibrate_model(cube, {material::Law::kLinear, 5000.0, 0.45}, region_method("surface", {{1, 1e4, 0.3}})),
               InvalidArgument);
}

}  // namespace
}  // namespace hooke::calibrate
