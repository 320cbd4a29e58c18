#pragma once
/// Node orderings for cache locality.
#include <hooke/mesh/mesh.hpp>
#include <vector>

namespace hooke::mesh {

/// Reverse Cuthill-McKee order of the nodes (Cuthill & McKee 1969, reversed as George 1971 suggests): breadth-
/// first from a pseudo-peripheral node of each connected component, neighbours by increasing degree, then
/// reversed. Nodes that share an element end up close, so element loops touch memory almost in order.
/// @param mesh  any mesh (nodes in no element come last)
/// @return new_to_old: entry k is the old index of the node placed at position k (a permutation of 0..#V-1)
std::vector<int> rcm_order(const Mesh& mesh);

/// The mesh with its nodes in the order new_to_old (elements renumbered; element order and regions kept, so
/// messages still name elements as the file does).
/// @throws InvalidArgument when new_to_old is not a permutation of the nodes
Mesh permute_nodes(const Mesh& mesh, const std::vector<int>& new_to_old);

/// Largest |i - j| over node pairs sharing an element: the bandwidth an ordering achieves.
int node_bandwidth(const Mesh& mesh);

}  // namespace hooke::mesh
