#include <algorithm>
#include <hooke/core/error.hpp>
#include <hooke/mesh/reorder.hpp>
#include <numeric>

namespace hooke::mesh {
namespace {

// Node adjacency in compressed rows, neighbours sorted.
struct Adjacency {
  std::vector<int> start, neighbours;
  int degree(int n) const { return start[static_cast<size_t>(n) + 1] - start[static_cast<size_t>(n)]; }
};

Adjacency adjacency(const Mesh& mesh) {
  const int n = mesh.node_count();
  std::vector<std::vector<int>> lists(static_cast<size_t>(n));
  for (int e = 0; e < mesh.element_count(); ++e)
    for (Eigen::Index a = 0; a < mesh.elements.cols(); ++a)
      for (Eigen::Index b = 0; b < mesh.elements.cols(); ++b)
        if (a != b) lists[static_cast<size_t>(mesh.elements(e, a))].push_back(mesh.elements(e, b));
  Adjacency adj;
  adj.start.push_back(0);
  for (auto& l : lists) {
    std::sort(l.begin(), l.end());
    l.erase(std::unique(l.begin(), l.end()), l.end());
    adj.neighbours.insert(adj.neighbours.end(), l.begin(), l.end());
    adj.start.push_back(static_cast<int>(adj.neighbours.size()));
  }
  return adj;
}

// Breadth-first levels from `root` over unvisited nodes (visited marks stay untouched); returns the visit order,
// neighbours taken by increasing degree (ties by index).
std::vector<int> breadth_first(const Adjacency& adj, int root, const std::vector<char>& visited) {
  std::vector<int> order{root};
  std::vector<char> seen = visited;
  seen[static_cast<size_t>(root)] = 1;
  std::vector<int> next;
  for (size_t head = 0; head < order.size(); ++head) {
    const int v = order[head];
    next.clear();
    for (int q = adj.start[static_cast<size_t>(v)]; q < adj.start[static_cast<size_t>(v) + 1]; ++q) {
      const int w = adj.neighbours[static_cast<size_t>(q)];
      if (!seen[static_cast<size_t>(w)]) {
        seen[static_cast<size_t>(w)] = 1;
        next.push_back(w);
      }
    }
    std::sort(next.begin(), next.end(),
              [&](int a, int b) { return adj.degree(a) != adj.degree(b) ? adj.degree(a) < adj.degree(b) : a < b; });
    order.insert(order.end(), next.begin(), next.end());
  }
  return order;
}

}  // namespace

std::vector<int> rcm_order(const Mesh& mesh) {
  const int n = mesh.node_count();
  const Adjacency adj = adjacency(mesh);
  std::vector<char> visited(static_cast<size_t>(n), 0);
  std::vector<int> order, isolated;
  order.reserve(static_cast<size_t>(n));
  for (int seed = 0; seed < n; ++seed) {
    if (visited[static_cast<size_t>(seed)]) continue;
    if (adj.degree(seed) == 0) {
      visited[static_cast<size_t>(seed)] = 1;
      isolated.push_back(seed);
      continue;
    }
    // Pseudo-peripheral root: twice restart from the last node reached, which lies in the deepest level.
    std::vector<int> component = breadth_first(adj, seed, visited);
    for (int pass = 0; pass < 2; ++pass) component = breadth_first(adj, component.back(), visited);
    for (int v : component) visited[static_cast<size_t>(v)] = 1;
    order.insert(order.end(), component.begin(), component.end());
  }
  std::reverse(order.begin(), order.end());
  order.insert(order.end(), isolated.begin(), isolated.end());
  return order;
}

Mesh permute_nodes(const Mesh& mesh, const std::vector<int>& new_to_old) {
  const int n = mesh.node_count();
  if (new_to_old.size() != static_cast<size_t>(n)) throw InvalidArgument("permute_nodes: one entry per node");
  std::vector<int> old_to_new(static_cast<size_t>(n), -1);
  for (int k = 0; k < n; ++k) {
    const int old = new_to_old[static_cast<size_t>(k)];
    if (old < 0 || old >= n || old_to_new[static_cast<size_t>(old)] >= 0)
      throw InvalidArgument("permute_nodes: not a permutation of the nodes");
    old_to_new[static_cast<size_t>(old)] = k;
  }
  Mesh out = mesh;
  for (int k = 0; k < n; ++k) out.nodes.row(k) = mesh.nodes.row(new_to_old[static_cast<size_t>(k)]);
  for (Eigen::Index e = 0; e < out.elements.rows(); ++e)
    for (Eigen::Index a = 0; a < out.elements.cols(); ++a)
      out.elements(e, a) = old_to_new[static_cast<size_t>(mesh.elements(e, a))];
  return out;
}

int node_bandwidth(const Mesh& mesh) {
  int band = 0;
  for (Eigen::Index e = 0; e < mesh.elements.rows(); ++e)
    band = std::max(band, mesh.elements.row(e).maxCoeff() - mesh.elements.row(e).minCoeff());
  return band;
}

}  // namespace hooke::mesh
