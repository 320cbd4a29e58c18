// A calibrated model against the FEM under the same contact: a sphere pressed into the top of a tissue cylinder to
// 20 % of its height, the force on the sphere and the displacement field at every depth (docs/contact.md).
#include <gtest/gtest.h>

#include <cstdio>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/core/error.hpp>
#include <hooke/experiments/contact_comparison.hpp>
#include <hooke/io/mesh_io.hpp>

namespace hooke::experiments {
namespace {

// cylinder_hole.msh (990 nodes, 20 mm high) at nu = 0.45 against the neo-Hookean FEM, a 5 mm sphere from touching the
// top to 4 mm into it in 4 steps. Measured (8 steps, docs/contact.md): the default model (stiffness-fit-volume) within
// 1.9-8.1 % in force and 0.12-0.19 relative L2; any-nu-tet within 0.9-4.9 % and 0.066-0.16 (0.066 at 20 %).
struct PressBounds {
  const char* method;
  double force, l2, l2_at_20;
};
class ContactComparison : public ::testing::TestWithParam<PressBounds> {};

TEST_P(ContactComparison, ACylinderPressedTo20PercentFollowsTheNeoHookeanFem) {
  const PressBounds bounds = GetParam();
  const mesh::Mesh m = io::read_mesh(std::string(HOOKE_MESH_DATA) + "/cylinder_hole.msh");
  calibrate::ModelOptions mo;
  mo.method = bounds.method;
  const calibrate::CalibratedModel model = calibrate::calibrate_model(m, {material::Law::kLinear, 14630.0, 0.45}, mo);
  const double top = m.nodes.col(2).maxCoeff(), height = top - m.nodes.col(2).minCoeff(), r = 0.005;
  ContactPressOptions o;
  o.start = {Vec3(0.0, 0.0, top + r), Mat3::Identity()};
  o.depth = 0.2 * height;
  o.steps = 4;
  const auto rows = compare_under_contact(model, contact::RigidTool(contact::ToolShape::kSphere, r), o);
  ASSERT_EQ(rows.size(), 4u);
  for (const ContactPressRow& row : rows) {
    std::printf("[contact %s] %.1f %%: FEM %.5f N, model %.5f N (%.3f), L2 %.3f, contacts %d/%d, gap %.2g m\n",
                model.method.c_str(), 100.0 * row.travel / height, row.fem_force.z(), row.model_force.z(),
                row.force_error, row.relative_l2, row.fem_contacts, row.model_contacts, row.smallest_gap);
    EXPECT_GT(row.smallest_gap, 0.0);
    EXPECT_GT(row.fem_force.z(), 0.0);
    EXPECT_LT(row.force_error, bounds.force);
    EXPECT_LT(row.relative_l2, bounds.l2);
  }
  EXPECT_LT(rows.back().relative_l2, bounds.l2_at_20);
  // the force grows with depth, and faster than linearly (the contact patch grows)
  EXPECT_GT(rows[3].fem_force.z() - rows[2].fem_force.z(), rows[1].fem_force.z() - rows[0].fem_force.z());
  ContactPressOptions bad = o;
  bad.depth = 0.0;
  EXPECT_THROW(compare_under_contact(model, contact::RigidTool(contact::ToolShape::kSphere, r), bad), InvalidArgument);
}

INSTANTIATE_TEST_SUITE_P(Models, ContactComparison,
                         ::testing::Values(PressBounds{"auto", 0.1, 0.25, 0.25},
                                           PressBounds{"any-nu-tet", 0.06, 0.2, 0.1}),
                         [](const auto& param_info) {
                           return std::string(param_info.param.method) == "auto" ? "Auto" : "AnyNuTet";
                         });

}  // namespace
}  // namespace hooke::experiments
