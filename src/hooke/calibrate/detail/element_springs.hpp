#pragma once
// The springs of a mesh (element edges, plus the two diagonals of each quad) and per-element accumulation.
#include <hooke/calibrate/spring_model.hpp>
#include <map>

namespace hooke::calibrate::detail {

class EdgeAccumulator {
 public:
  explicit EdgeAccumulator(const mesh::Mesh& mesh);
  // Calls fn(spring index, rest distance) for every spring of element e (3 for triangles, 6 for quads and tets).
  template <typename Fn>
  void for_each_edge(int e, Fn&& fn) const {
    for (int s : element_springs(e)) fn(s, m_length(s));
  }
  std::vector<int> element_springs(int e) const;  // in the local order of local_pairs()
  // Local node pairs of an element's springs, in the order of element_springs().
  const std::vector<std::array<int, 2>>& local_pairs() const { return m_local; }
  void add(int spring, double stiffness) { m_stiffness(spring) += stiffness; }
  bool is_diagonal(int spring) const { return m_diagonal[static_cast<size_t>(spring)] != 0; }
  SpringModel finish() const;

 private:
  const mesh::Mesh& m_mesh;
  std::map<std::array<int, 2>, int> m_index;
  std::vector<std::array<int, 2>> m_pairs, m_local;
  std::vector<char> m_diagonal;
  VecX m_length, m_stiffness;
};

}  // namespace hooke::calibrate::detail
