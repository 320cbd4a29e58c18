// A model's kind decides how it is built, compared and remade: calibrations, the surface model and the FEM model
// carry theirs; a model whose method hooke does not know (identified, hand-tuned) is a "file" model.
#include <gtest/gtest.h>

#include <hooke/calibrate/method.hpp>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/core/error.hpp>
#include <hooke/mesh/generators.hpp>
#include <set>

namespace hooke::calibrate {
namespace {

const material::Material kRubber{material::Law::kLinear, 1e5, 0.3};

CalibratedModel made(const mesh::Mesh& m, const std::string& method) {
  ModelOptions o;
  o.method = method;
  return calibrate_model(m, kRubber, o);
}

TEST(ModelKind, EachFactoryMethodMakesAModelOfItsKind) {
  const mesh::Mesh tets = mesh::tet_box(1.0, 1.0, 1.0, 2, 2, 2);
  EXPECT_EQ(model_kind(made(tets, "lloyd-tet")), ModelKind::kSprings);
  EXPECT_EQ(model_kind(made(tets, "any-nu-tet")), ModelKind::kSprings);
  EXPECT_EQ(model_kind(made(tets, "auto")), ModelKind::kSprings);
  const CalibratedModel fem = made(tets, "fem");
  EXPECT_EQ(model_kind(fem), ModelKind::kFem);
  EXPECT_TRUE(fem.springs.pairs.empty());
  EXPECT_EQ(build_model(fem).model->blocks().front()->name(), "fem");  // built by kind: the FEM block
  EXPECT_EQ(model_kind(made(mesh::cube_surface(3, 1.0), "surface")), ModelKind::kSurface);
}

TEST(ModelKind, AMethodHookeDoesNotKnowIsAFileModel) {
  CalibratedModel tuned = made(mesh::tet_box(1.0, 1.0, 1.0, 1, 1, 1), "lloyd-tet");
  tuned.method = "hand-tuned";
  EXPECT_EQ(model_kind(tuned), ModelKind::kFile);
  EXPECT_NO_THROW(build_model(tuned));  // its springs still build
  tuned.method = "identified";
  EXPECT_EQ(model_kind(tuned), ModelKind::kFile);
}

TEST(ModelKind, NamesMapToKindsAndUnknownNamesAreRefused) {
  EXPECT_EQ(model_kind_of_method("stiffness-fit-volume"), ModelKind::kSprings);
  EXPECT_EQ(model_kind_of_method("auto"), ModelKind::kSprings);
  for (const ModelKind k : {ModelKind::kSurface, ModelKind::kFem, ModelKind::kFile})
    EXPECT_EQ(model_kind_of_method(model_kind_name(k)), k);
  EXPECT_EQ(model_kind_name(ModelKind::kFile), "file");
  try {
    model_kind_of_method("springz");
    FAIL() << "no throw";
  } catch (const InvalidArgument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("unknown model method 'springz'"), std::string::npos) << what;
    EXPECT_NE(what.find("any-nu-tet"), std::string::npos) << what;
    EXPECT_NE(what.find("file"), std::string::npos) << what;
  }
}

// Every name the factory takes states its equation, from one table for the calibration methods; the equations
// differ from method to method, and an unknown name is refused.
TEST(MethodEquation, EveryFactoryNameHasItsOwn) {
  std::set<std::string> seen;
  for (const std::string& name : model_method_names()) {
    const std::string eq = method_equation(name);
    EXPECT_FALSE(eq.empty()) << name;
    EXPECT_TRUE(seen.insert(eq).second) << name << " repeats " << eq;
  }
  for (const std::string_view name : method_names())
    EXPECT_EQ(method_equation(std::string(name)), method_equation(method_from_name(name)));
  EXPECT_NE(method_equation("lloyd-tet").find("Eq. 12"), std::string::npos);
  EXPECT_THROW(method_equation("lloyd"), InvalidArgument);
}

}  // namespace
}  // namespace hooke::calibrate
