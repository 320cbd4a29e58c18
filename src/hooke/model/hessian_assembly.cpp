#include <algorithm>
#include <cstdint>
#include <hooke/core/error.hpp>
#include <hooke/model/hessian_assembly.hpp>

namespace hooke::model {
namespace {

std::vector<const TermBlock*> blocks_of(const Model& model) {
  std::vector<const TermBlock*> blocks;
  for (const auto& b : model.blocks()) blocks.push_back(b.get());
  return blocks;
}

}  // namespace

HessianAssembly::HessianAssembly(const Model& model)
    : HessianAssembly(model.dim(), model.dof_count(), blocks_of(model)) {}

HessianAssembly::HessianAssembly(int dim, int dof_count, std::vector<const TermBlock*> blocks)
    : m_blocks(std::move(blocks)) {
  if (dim != 2 && dim != 3) throw InvalidArgument("HessianAssembly: dim must be 2 or 3");
  const int nodes = dof_count / dim;
  std::vector<RowMatXi> elements;
  // Node adjacency per column node, every node adjacent to itself: the rows of each column gathered (counted
  // first), then sorted and made unique column by column (a few dozen entries each, where one sort of all the
  // pairs of a scan's 345 000 tets took seconds).
  for (const TermBlock* b : m_blocks) elements.push_back(b->element_nodes());
  std::vector<int> adj_start(static_cast<size_t>(nodes) + 1, 1);
  adj_start[0] = 0;
  for (size_t k = 0; k < elements.size(); ++k) {
    const RowMatXi& el = elements[k];
    for (Eigen::Index e = 0; e < el.rows(); ++e)
      for (Eigen::Index a = 0; a < el.cols(); ++a) {
        const int node = el(e, a);
        if (node < 0 || node >= nodes)
          throw InvalidArgument("block '" + std::string(m_blocks[k]->name()) + "' element " + std::to_string(e) +
                                " names a node outside the model");
        adj_start[static_cast<size_t>(node) + 1] += static_cast<int>(el.cols());
      }
  }
  std::vector<std::int64_t> fill_at(static_cast<size_t>(nodes) + 1, 0);
  for (int i = 0; i < nodes; ++i)
    fill_at[static_cast<size_t>(i) + 1] = fill_at[static_cast<size_t>(i)] + adj_start[static_cast<size_t>(i) + 1];
  std::vector<int> adj(static_cast<size_t>(fill_at.back()));
  std::vector<std::int64_t> next(fill_at.begin(), fill_at.end() - 1);
  for (int i = 0; i < nodes; ++i) adj[static_cast<size_t>(next[static_cast<size_t>(i)]++)] = i;
  for (const RowMatXi& el : elements)
    for (Eigen::Index e = 0; e < el.rows(); ++e)
      for (Eigen::Index c = 0; c < el.cols(); ++c) {
        const auto col = static_cast<size_t>(el(e, c));
        for (Eigen::Index a = 0; a < el.cols(); ++a) adj[static_cast<size_t>(next[col]++)] = el(e, a);
      }
  next = {};
  size_t kept = 0;
  for (int i = 0; i < nodes; ++i) {
    const auto first = adj.begin() + fill_at[static_cast<size_t>(i)];
    const auto last = adj.begin() + fill_at[static_cast<size_t>(i) + 1];
    std::sort(first, last);
    const auto end = std::unique(first, last);
    const auto count = static_cast<size_t>(end - first);
    if (static_cast<std::int64_t>(kept) < fill_at[static_cast<size_t>(i)])  // moved down, never onto itself
      std::copy(first, end, adj.begin() + static_cast<std::ptrdiff_t>(kept));
    kept += count;
    adj_start[static_cast<size_t>(i) + 1] = static_cast<int>(kept);
  }
  adj.resize(kept);
  adj.shrink_to_fit();
  auto degree = [&](int n) { return adj_start[static_cast<size_t>(n) + 1] - adj_start[static_cast<size_t>(n)]; };
  auto column_start = [&](int n) { return dim * dim * adj_start[static_cast<size_t>(n)]; };
  auto rank = [&](int row, int col) {
    const auto first = adj.begin() + adj_start[static_cast<size_t>(col)];
    return static_cast<int>(std::lower_bound(first, adj.begin() + adj_start[static_cast<size_t>(col) + 1], row) -
                            first);
  };

  const auto nnz = static_cast<Eigen::Index>(dim) * dim * static_cast<Eigen::Index>(adj.size());
  if (nnz > INT32_MAX) throw InvalidArgument("HessianAssembly: the pattern exceeds 2^31 entries");
  m_matrix = SparseMatrix(dof_count, dof_count);
  m_matrix.resizeNonZeros(nnz);
  int* outer = m_matrix.outerIndexPtr();
  int* inner = m_matrix.innerIndexPtr();
  m_diagonal.resize(static_cast<size_t>(dof_count));
  for (int n = 0; n < nodes; ++n) {
    const int deg = degree(n);
    for (int k = 0; k < dim; ++k) {
      const int start = column_start(n) + k * dim * deg;
      outer[dim * n + k] = start;
      for (int r = 0; r < deg; ++r)
        for (int i = 0; i < dim; ++i)
          inner[start + dim * r + i] = dim * adj[static_cast<size_t>(adj_start[static_cast<size_t>(n)] + r)] + i;
      m_diagonal[static_cast<size_t>(dim * n + k)] = start + dim * rank(n, n) + k;
    }
  }
  outer[dof_count] = static_cast<int>(nnz);
  std::fill(m_matrix.valuePtr(), m_matrix.valuePtr() + nnz, 0.0);

  for (const RowMatXi& el : elements) {
    HessianScatter s;
    s.dim = dim;
    s.nodes_per_element = static_cast<int>(el.cols());
    const auto npe = static_cast<size_t>(el.cols());
    s.base.resize(static_cast<size_t>(el.rows()) * npe * npe);
    s.stride.resize(static_cast<size_t>(el.rows()) * npe);
    for (Eigen::Index e = 0; e < el.rows(); ++e)
      for (size_t b = 0; b < npe; ++b) {
        const int col = el(e, static_cast<Eigen::Index>(b));
        s.stride[static_cast<size_t>(e) * npe + b] = dim * degree(col);
        for (size_t a = 0; a < npe; ++a)
          s.base[(static_cast<size_t>(e) * npe + a) * npe + b] =
              column_start(col) + dim * rank(el(e, static_cast<Eigen::Index>(a)), col);
      }
    m_scatter.push_back(std::move(s));
  }
}

void HessianAssembly::assemble(const Eigen::Ref<const VecX>& x, bool project_psd, const Interaction* interaction) {
  double* values = m_matrix.valuePtr();
  std::fill(values, values + m_matrix.nonZeros(), 0.0);
  for (size_t b = 0; b < m_blocks.size(); ++b) {
    if (m_scatter[b].base.empty()) continue;
    if (interaction && m_blocks[b]->follows_interaction())
      m_blocks[b]->add_interaction_hessian_values(x, *interaction, m_scatter[b], values, project_psd);
    else
      m_blocks[b]->add_hessian_values(x, m_scatter[b], values, project_psd);
  }
}

SparseMatrix block_hessian(const TermBlock& block, int dim, const Eigen::Ref<const VecX>& x, bool project_psd) {
  HessianAssembly assembly(dim, static_cast<int>(x.size()), {&block});
  assembly.assemble(x, project_psd);
  return assembly.matrix();
}

}  // namespace hooke::model
