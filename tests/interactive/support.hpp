#pragma once
// What the interactive layer's tests share: settings and a small cylinder.
#include <hooke/interactive/live_simulation.hpp>
#include <hooke/mesh/generators.hpp>
#include <string>

namespace hooke::interactive {

inline LiveSettings settings(const std::string& method = "lloyd-tet", double nu = 0.3) {
  LiveSettings s;
  s.model.method = method;
  s.material = {material::Law::kLinear, 14630.0, nu};
  s.dynamics.damping_mass = 60.0;
  return s;
}

inline mesh::Mesh cylinder() { return mesh::tet_cylinder(0.01, 0.02, 8, 5); }

// The top node nearest the axis.
inline int top_node(const mesh::Mesh& m) {
  int best = 0;
  for (int i = 0; i < m.node_count(); ++i) {
    const auto x = m.nodes.row(i), b = m.nodes.row(best);
    if (x(2) > b(2) + 1e-12 || (std::abs(x(2) - b(2)) < 1e-12 && x.head(2).norm() < b.head(2).norm())) best = i;
  }
  return best;
}

}  // namespace hooke::interactive
