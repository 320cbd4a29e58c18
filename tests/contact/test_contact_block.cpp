// Contact with rigid tools, checked against independent derivations: the signed distance's derivatives and the
// barrier's against central differences, the block's gradient and Hessian against the energy's, and a pressed FEM
// block against force balance and Hertz's solution for a sphere on a half-space.
#include <gtest/gtest.h>

#include <cmath>
#include <hooke/contact/contact_block.hpp>
#include <hooke/contact/rigid_tool.hpp>
#include <hooke/core/error.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/model/hessian_assembly.hpp>
#include <hooke/model/model.hpp>
#include <hooke/model/problem.hpp>
#include <hooke/model/support.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <hooke/solve/tool_press.hpp>
#include <iostream>
#include <random>
#include <utility>

#include <hooke/core/symmetric_eigen.hpp>
#include "support/finite_difference.hpp"
#include "support/meshes.hpp"

namespace hooke::contact {
namespace {

Mat3 rotation(double angle, const Vec3& axis) { return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(); }

// The distance's normal and curvature against central differences of the distance and the normal, at points around
// each shape (beside a capsule's shaft and beyond its caps), in a rotated pose.
TEST(RigidTool, DistanceDerivativesMatchFiniteDifferences) {
  std::mt19937 rng(5);
  std::normal_distribution<double> n(0.0, 0.01);
  for (const RigidTool& shape : {RigidTool(ToolShape::kSphere, 0.004), RigidTool(ToolShape::kCapsule, 0.003, 0.02),
                                 RigidTool(ToolShape::kHalfSpace)}) {
    RigidTool tool = shape;
    tool.set_pose({Vec3(0.001, -0.002, 0.003), rotation(0.7, Vec3(1.0, 2.0, 0.5))});
    for (int trial = 0; trial < 20; ++trial) {
      const Vec3 p = tool.pose().position + Vec3(n(rng), n(rng), n(rng));
      const SurfaceDistance s = tool.distance(p);
      const auto d = [&](const VecX& q) { return tool.distance(Vec3(q)).distance; };
      const auto normal = [&](const VecX& q) { return VecX(tool.distance(Vec3(q)).normal); };
      const VecX fd = test::fd_gradient(d, VecX(p), 1e-7);
      EXPECT_LT((fd - s.normal).norm(), 1e-6) << tool.description() << " at " << p.transpose();
      const MatX fd2 = test::fd_jacobian(normal, VecX(p), 1e-7);
      EXPECT_LT((fd2 - s.curvature).norm(), 1e-4 * (1.0 + s.curvature.norm())) << tool.description();
      EXPECT_NEAR(tool.distance(s.closest).distance, 0.0, 1e-12) << tool.description();
      EXPECT_EQ(tool.signed_distance(p), s.distance) << tool.description();
      EXPECT_NEAR((p - s.closest).norm(), std::abs(s.distance), 1e-12) << tool.description();
    }
  }
  EXPECT_NEAR(RigidTool(ToolShape::kSphere, 0.01).distance(Vec3(0.0, 0.0, 0.03)).distance, 0.02, 1e-15);
  RigidTool capsule(ToolShape::kCapsule, 0.01, 0.1);                           // along z, centred on the origin
  EXPECT_NEAR(capsule.distance(Vec3(0.02, 0.0, 0.04)).distance, 0.01, 1e-15);  // beside the shaft
  EXPECT_NEAR(capsule.distance(Vec3(0.0, 0.0, -0.07)).distance, 0.01, 1e-15);  // beyond a cap
  EXPECT_NEAR(RigidTool(ToolShape::kHalfSpace).distance(Vec3(5.0, 3.0, -0.2)).distance, -0.2, 1e-15);
}

TEST(RigidTool, ParsesAndRefusesDescriptions) {
  EXPECT_EQ(parse_tool("sphere:5", 1e-3).radius(), 0.005);
  const RigidTool capsule = parse_tool("capsule:2,30", 1e-3);
  EXPECT_EQ(capsule.shape(), ToolShape::kCapsule);
  EXPECT_NEAR(capsule.length(), 0.03, 1e-15);
  EXPECT_EQ(parse_tool("plane").shape(), ToolShape::kHalfSpace);
  // a mesh tool from a file read in mm (the file's 0.01 becomes 10 um), rounded by 0.5 mm
  const RigidTool mesh = parse_tool("mesh:" + std::string(HOOKE_MESH_DATA) + "/sphere_surface.msh,0.5", 1e-3);
  EXPECT_EQ(mesh.shape(), ToolShape::kMesh);
  EXPECT_NEAR(mesh.triangles()->rounding(), 5e-4, 1e-15);
  EXPECT_NEAR(mesh.signed_distance(Vec3(0.0, 0.0, 0.0)), -1e-5 - 5e-4, 1e-6);  // its centre, 10 mm deep
  EXPECT_NE(mesh.description().find("sphere_surface.msh,0.0005"), std::string::npos) << mesh.description();
  EXPECT_THROW(parse_tool("mesh:" + std::string(HOOKE_MESH_DATA) + "/cylinder.msh"), InvalidArgument);  // tets
  for (const char* bad : {"sphere", "sphere:-1", "sphere:x", "cube:3", "capsule:2", "capsule:1,-2"})
    EXPECT_THROW(parse_tool(bad), InvalidArgument) << bad;
  const RigidTool floor = parse_obstacle("plane:0,0,-0.01");
  EXPECT_NEAR(floor.distance(Vec3(0.3, 0.2, 0.0)).distance, 0.01, 1e-15);
  const RigidTool wall = parse_obstacle("plane:1,0,0,-2,0,0");  // outward normal -x
  EXPECT_NEAR(wall.distance(Vec3(0.5, 7.0, 3.0)).distance, 0.5, 1e-15);
  EXPECT_LT((rotation_to(Vec3(0.0, 3.0, 4.0)).col(2) - Vec3(0.0, 0.6, 0.8)).norm(), 1e-15);
  for (const char* bad : {"plane", "plane:1,2", "plane:0,0,0,0,0,0", "floor:0,0,0", "plane:0,0,x"})
    EXPECT_THROW(parse_obstacle(bad), InvalidArgument) << bad;
  RigidTool tool(ToolShape::kSphere, 0.01);
  EXPECT_THROW(tool.set_pose({Vec3(NAN, 0.0, 0.0), Mat3::Identity()}), InvalidArgument);
  EXPECT_THROW(tool.set_pose({Vec3::Zero(), 2.0 * Mat3::Identity()}), InvalidArgument);
}

TEST(Barrier, DerivativesMatchFiniteDifferencesAndItVanishesSmoothlyAtTheActivationDistance) {
  const double dhat = 1e-3;
  for (double d : {1e-6, 1e-5, 1e-4, 5e-4, 9e-4, 9.99e-4}) {
    const Barrier b = barrier(d, dhat);
    const double h = 1e-4 * std::min(d, dhat - d);  // both sides inside (0, dhat)
    EXPECT_NEAR(b.slope, (barrier(d + h, dhat).value - barrier(d - h, dhat).value) / (2 * h),
                1e-6 * std::abs(b.slope) + 1e-12);
    EXPECT_NEAR(b.curvature, (barrier(d + h, dhat).slope - barrier(d - h, dhat).slope) / (2 * h),
                1e-6 * std::abs(b.curvature) + 1e-9);
    EXPECT_GT(b.value, 0.0);
    EXPECT_LT(b.slope, 0.0);
    EXPECT_GT(b.curvature, 0.0);
  }
  EXPECT_EQ(barrier(dhat, dhat).value, 0.0);
  EXPECT_LT(barrier(dhat * (1 - 1e-6), dhat).value, 1e-18);  // C1 at dhat: value and slope go to zero
  EXPECT_TRUE(std::isinf(barrier(0.0, dhat).value));
  EXPECT_TRUE(std::isinf(barrier(-1e-3, dhat).value));
  // The pressure a node can carry at half the activation distance is kappa |b'(dhat/2)| = 1.19 kappa dhat, so with
  // kappa = E A / dhat any pressure up to E keeps a node in (dhat/2, dhat).
  EXPECT_NEAR(-barrier(0.5 * dhat, dhat).slope / dhat, std::log(2.0) + 0.5, 1e-12);
}

// The block's energy, gradient and Hessian at x (four nodes, the last out of reach) against central differences of
// step h, its projected Hessian positive semi-definite, and the force on the tool minus the sum of the nodes' forces.
// Returns the gradient.
VecX expect_derivatives_match(const ContactBlock& block, const VecX& x, double h) {
  VecX g = VecX::Zero(x.size());
  EXPECT_NEAR(block.energy_and_add_gradient(x, g), block.energy(x), 1e-15);
  const VecX fd = test::fd_gradient([&](const VecX& q) { return block.energy(q); }, x, h);
  EXPECT_LT((fd - g).norm(), 1e-6 * g.norm());
  model::Model m(3, x);
  m.add(std::make_unique<ContactBlock>(block));
  const MatX hessian = MatX(m.hessian(x));
  const MatX fdh = test::fd_jacobian([&](const VecX& q) { return m.gradient(q); }, x, 0.1 * h);
  EXPECT_LT((hessian - fdh).norm(), 1e-5 * hessian.norm());
  EXPECT_GE(symmetric_eigenvalues(MatX(m.hessian(x, true))).minCoeff(), -1e-9 * hessian.norm());
  EXPECT_LT((block.tool_force(x) - Vec3(g.segment<3>(0) + g.segment<3>(3) + g.segment<3>(6))).norm(), 1e-12 * g.norm());
  return g;
}

// The block on a few nodes near a sphere: energy, gradient and Hessian against central differences.
TEST(ContactBlock, GradientAndHessianMatchFiniteDifferences) {
  auto tool = std::make_shared<RigidTool>(ToolShape::kSphere, 0.01);
  tool->set_pose({Vec3(0.0, 0.0, 0.0), Mat3::Identity()});
  const double dhat = 2e-3;
  VecX x(12);
  x << 0.0111, 0.0, 0.0, 0.0, 0.0105, 0.001, 0.003, 0.002, 0.0112, 0.02, 0.0, 0.0;  // the last one out of reach
  ContactBlock block({0, 1, 2, 3}, VecX::Constant(4, 50.0), dhat, tool);
  EXPECT_EQ(block.active_count(x), 3);
  const VecX g = expect_derivatives_match(block, x, 1e-8);
  // its torque about the centre is zero for a sphere
  EXPECT_LT(block.tool_torque(x).norm(), 1e-12 * g.norm() * 0.01);
  // inside the tool: inadmissible
  x(0) = 0.009;
  EXPECT_TRUE(std::isinf(block.energy(x)));
  EXPECT_THROW(ContactBlock({0}, VecX::Constant(1, -1.0), dhat, tool), InvalidArgument);
  EXPECT_THROW(ContactBlock({0}, VecX::Constant(2, 1.0), dhat, tool), InvalidArgument);
  EXPECT_THROW(ContactBlock({0}, VecX::Constant(1, 1.0), 0.0, tool), InvalidArgument);
}

// The friction smoothing: f1 = f0', f1' = f1'' against central differences, C1 at eps, f1 rising from 0 to 1.
TEST(Friction, SmoothingDerivativesMatchFiniteDifferences) {
  const double eps = 1e-6;
  for (double y : {0.0, 1e-8, 3e-7, 9e-7, 1.5e-6, 1e-3}) {
    const double h = 1e-10;
    const FrictionSmoothing f = friction_smoothing(y, eps);
    EXPECT_NEAR(f.slope, (friction_smoothing(y + h, eps).value - friction_smoothing(y - h, eps).value) / (2 * h), 1e-6);
    EXPECT_NEAR(f.curvature, (friction_smoothing(y + h, eps).slope - friction_smoothing(y - h, eps).slope) / (2 * h),
                1e-4 / eps);
    EXPECT_GE(f.slope, 0.0);
    EXPECT_LE(f.slope, 1.0);
  }
  EXPECT_EQ(friction_smoothing(0.0, eps).value, 0.0);
  EXPECT_NEAR(friction_smoothing(eps * (1 - 1e-9), eps).value, friction_smoothing(eps, eps).value, 1e-14);
  EXPECT_NEAR(friction_smoothing(eps * (1 - 1e-9), eps).slope, 1.0, 1e-8);
}

// Friction on nodes touching a moving, turning capsule: lagged at one pose, evaluated after the tool moved and the
// nodes slipped (some below eps, some beyond): gradient and Hessian against central differences, the force on the
// tool against the nodes' forces, and no slip force beyond mu times the lagged normal force.
TEST(Friction, GradientAndHessianMatchFiniteDifferencesAndTheForceIsBoundedByMuTimesTheNormalForce) {
  auto tool = std::make_shared<RigidTool>(ToolShape::kCapsule, 0.01, 0.02);
  tool->set_pose({Vec3(0.0, 0.0, 0.0), rotation(0.3, Vec3(1.0, 0.0, 0.0))});
  const double dhat = 2e-3, mu = 0.4, eps = 1e-4;
  VecX x(12);
  x << 0.0111, 0.0, 0.0, 0.0, -0.01159, -0.00044, 0.003, 0.0112, 0.002, 0.03, 0.0, 0.0;
  ContactBlock block({0, 1, 2, 3}, VecX::Constant(4, 50.0), dhat, tool);
  block.set_friction({mu, eps});
  block.lag(x);
  EXPECT_EQ(block.sticking_count(), 3);
  const ContactBlock copy = block;  // shares the lagged state
  EXPECT_EQ(copy.sticking_count(), 3);
  VecX normal = VecX::Zero(12);
  {
    ContactBlock frictionless({0, 1, 2, 3}, VecX::Constant(4, 50.0), dhat, tool);
    frictionless.add_gradient(x, normal);
  }
  tool->set_pose({Vec3(1e-5, 2e-5, -1e-5), rotation(0.31, Vec3(1.0, 0.1, 0.0))});
  x.segment<3>(0) += Vec3(0.0, 3e-5, 1e-5);   // slips beyond eps relative to the tool
  x.segment<3>(3) += Vec3(1e-5, 0.0, -1e-6);  // about eps
  x.segment<3>(6) += Vec3(-2e-5, 1e-5, 0.0);
  const VecX g = expect_derivatives_match(block, x, 1e-9);
  // the friction force (the total less the barrier's at x) is at most mu times the lagged normal force
  VecX barrier_only = VecX::Zero(12);
  ContactBlock({0, 1, 2, 3}, VecX::Constant(4, 50.0), dhat, tool).add_gradient(x, barrier_only);
  for (int i = 0; i < 3; ++i)
    EXPECT_LE((g - barrier_only).segment<3>(3 * i).norm(), mu * normal.segment<3>(3 * i).norm() * (1 + 1e-12));
  EXPECT_THROW(block.set_friction({-0.1, eps}), InvalidArgument);
  EXPECT_THROW(block.set_friction({0.1, 0.0}), InvalidArgument);
}

}  // namespace
}  // namespace hooke::contact

namespace hooke::contact {
namespace {

// A box [0, l] x [0, l] x [0, h] of tets graded towards the centre of its top face (cells there about 1/q^2 of the
// mean), where a sphere will press.
mesh::Mesh graded_block(double l, double h, int n, int layers, double grading) {
  mesh::Mesh m = mesh::tet_box(l, l, h, n, n, layers);
  for (Eigen::Index i = 0; i < m.nodes.rows(); ++i) {
    for (int a = 0; a < 2; ++a) {
      const double s = 2.0 * m.nodes(i, a) / l - 1.0;
      m.nodes(i, a) = 0.5 * l * (1.0 + std::copysign(std::pow(std::abs(s), grading), s));
    }
    m.nodes(i, 2) = h * (1.0 - std::pow(1.0 - m.nodes(i, 2) / h, grading));
  }
  return m;
}

struct PressedBlock {
  mesh::Mesh mesh;
  std::shared_ptr<RigidTool> tool;
  std::shared_ptr<model::Model> model;
  const ContactBlock* block = nullptr;
  model::Problem problem;
};

// The block's FEM (linear elasticity, E, nu) with a contact block on its top face for a sphere of radius r, the
// bottom clamped.
PressedBlock pressed_block(const mesh::Mesh& mesh, const material::Material& material, double radius, double dhat) {
  PressedBlock p{mesh, std::make_shared<RigidTool>(ToolShape::kSphere, radius), nullptr, nullptr, {}};
  const double top = mesh.nodes.col(2).maxCoeff();
  const model::BoundaryFacets b = model::boundary_facets_with_geometry(mesh);
  VecX area = VecX::Zero(mesh.node_count());
  for (Eigen::Index f = 0; f < b.facets.rows(); ++f)
    for (int a = 0; a < 3; ++a) area(b.facets(f, a)) += b.measures(f) / 3.0;
  std::vector<int> nodes, bottom;
  std::vector<double> shares;
  for (int i = 0; i < mesh.node_count(); ++i) {
    if (mesh.nodes(i, 2) > top - 1e-12) nodes.push_back(i), shares.push_back(area(i));
    if (mesh.nodes(i, 2) < 1e-12) bottom.push_back(i);
  }
  const VecX kappa = contact_stiffness(material.youngs_modulus,
                                       Eigen::Map<VecX>(shares.data(), static_cast<Eigen::Index>(shares.size())), dhat);
  p.model = std::make_shared<model::Model>(3, mesh::flat_positions(mesh));
  p.model->add(fem::make_elastic_block(mesh, material));
  auto block = std::make_unique<ContactBlock>(nodes, kappa, dhat, p.tool);
  p.block = block.get();
  p.model->add(std::move(block));
  p.problem = model::make_problem(p.model);
  model::fix_nodes(p.problem, bottom);
  return p;
}

// Hertz (1882): a rigid sphere of radius R pressed a depth d into an elastic half-space needs
// F = 4/3 E / (1 - nu^2) sqrt(R) d^(3/2). A 60 x 60 x 30 mm block, a 10 mm sphere, 1 mm deep (contact radius
// sqrt(R d) = 3.2 mm, a tenth of the block's depth), frictionless, on two graded meshes. Every step keeps every node
// outside the sphere and within the activation distance of it where they touch, the force on the sphere balances the
// supports' reaction, and the force approaches Hertz's from above as the mesh is refined (linear tets are too stiff:
// measured 1.91, 1.28, 1.31 and 1.19 times Hertz at 8, 12, 16 and 24 cells across; docs/contact.md).
TEST(ContactPress, ASpherePressedIntoAnFemBlockApproachesHertz) {
  const material::Material material{material::Law::kLinear, 1e4, 0.3};
  const double l = 0.06, h = 0.03, radius = 0.01, dhat = 1e-5, depth = 1e-3;
  const double hertz = 4.0 / 3.0 * material.youngs_modulus / (1.0 - 0.09) * std::sqrt(radius) * std::pow(depth, 1.5);
  std::vector<double> ratios;
  for (const auto& [n, layers] : {std::pair{8, 6}, std::pair{12, 8}}) {
    PressedBlock p = pressed_block(graded_block(l, h, n, layers, 2.0), material, radius, dhat);
    std::vector<Pose> poses;
    for (int k = 1; k <= 5; ++k)
      poses.push_back({Vec3(0.5 * l, 0.5 * l, h + radius - 0.2 * k * depth), Mat3::Identity()});
    const std::vector<solve::ToolPressStep> steps = solve::press_quasi_statically(p.problem, *p.block, *p.tool, poses);
    ASSERT_EQ(steps.size(), poses.size());
    for (const solve::ToolPressStep& step : steps) {
      EXPECT_GT(step.smallest_distance, 0.0);
      EXPECT_LT(step.smallest_distance, dhat);
      EXPECT_GT(step.active, 0);
      // force balance: the contact force on the sphere is what the clamped bottom holds
      VecX g = VecX::Zero(p.model->dof_count());
      p.model->blocks()[0]->add_gradient(step.positions, g);
      Vec3 support = Vec3::Zero();
      for (std::size_t dof = 0; dof < p.problem.fixed_dofs.size(); ++dof)
        if (p.problem.fixed_dofs[dof]) support(static_cast<int>(dof % 3)) += g(static_cast<Eigen::Index>(dof));
      EXPECT_LT((support - step.tool_force).norm(), 1e-6 * step.tool_force.norm());
    }
    ratios.push_back(steps.back().tool_force.z() / hertz);  // the body pushes the sphere up
    std::cout << "[hertz] " << n << " cells across: F / F_Hertz at 1 mm = " << ratios.back() << ", "
              << steps.back().active << " nodes in contact\n";
  }
  EXPECT_GT(ratios[1], 1.0);
  EXPECT_LT(ratios[1], ratios[0] - 0.1);
  EXPECT_LT(ratios[0], 2.0);
}

}  // namespace
}  // namespace hooke::contact
