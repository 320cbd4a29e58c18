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
  // Adds a prestress coefficient a = k (1 - l0/l) (N/m) to a spring: with it, the spring's linearised
  // stiffness is a I + b u u^T where b is what add() accumulated; finish() turns (a, b) into k = a + b and
  // l0 = l b / k (Lloyd Eq. 11 generalised). Only meaningful when the a of each element is a self-stress.
  void add_prestress(int spring, double a) { m_prestress(spring) += a; }
  bool is_diagonal(int spring) const { return m_diagonal[static_cast<size_t>(spring)] != 0; }
  SpringModel finish() const;

 private:
  const mesh::Mesh& m_mesh;
  std::map<std::array<int, 2>, int> m_index;
  std::vector<std::array<int, 2>> m_pairs, m_local;
  std::vector<char> m_diagonal;
  VecX m_length, m_stiffness, m_prestress;
};

}  // namespace hooke::calibrate::detail
