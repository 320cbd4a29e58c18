// model::FreeMap: restriction of assembled vectors and matrices to the free DOFs.
#include <gtest/gtest.h>

#include <hooke/fem/elastic_block.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/free_map.hpp>

namespace hooke::model {
namespace {

// The restricted stiffness is the dense matrix's free rows and columns picked one by one, with the same stored
// pattern (explicit zeros included) in sorted compressed form; vectors likewise.
TEST(FreeMap, RestrictPicksTheFreeRowsAndColumns) {
  const mesh::Mesh m = mesh::tet_box(0.02, 0.01, 0.01, 2, 1, 1);
  const auto model = fem::linear_model(m, {{material::Law::kLinear, 1000.0, 0.3}});
  const VecX rest = Eigen::Map<const VecX>(m.nodes.data(), m.nodes.size());
  SparseMatrix k = model->hessian(rest);
  k.coeffRef(0, 0) = 0.0;  // a stored zero stays stored
  std::vector<int> free;
  for (int i = 0; i < model->dof_count(); ++i)
    if (i % 7 != 2 && i != 0 && i != model->dof_count() - 1) free.push_back(i);
  free.insert(free.begin(), 0);
  const FreeMap map(free, model->dof_count());
  const SparseMatrix r = map.restrict(k);
  ASSERT_TRUE(r.isCompressed());
  const MatX dense = MatX(k);
  Eigen::Index stored = 0;
  for (int col : free)
    for (SparseMatrix::InnerIterator it(k, col); it; ++it) stored += map.to_free[static_cast<size_t>(it.row())] >= 0;
  EXPECT_EQ(r.nonZeros(), stored);
  for (int c = 0; c < map.size(); ++c) {
    int previous = -1;
    for (SparseMatrix::InnerIterator it(r, c); it; ++it) {
      EXPECT_GT(it.row(), previous);
      previous = static_cast<int>(it.row());
    }
    for (int row = 0; row < map.size(); ++row)
      EXPECT_EQ(r.coeff(row, c), dense(free[static_cast<size_t>(row)], free[static_cast<size_t>(c)]));
  }
  const VecX full = VecX::LinSpaced(model->dof_count(), 1.0, 2.0);
  const VecX part = map.restrict(full);
  for (int i = 0; i < map.size(); ++i) EXPECT_EQ(part(i), full(free[static_cast<size_t>(i)]));
}

}  // namespace
}  // namespace hooke::model
