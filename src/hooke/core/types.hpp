#pragma once
/// Common numeric types. SI units everywhere inside the library (m, Pa, N, kg, s).
#include <Eigen/Dense>
#include <Eigen/SparseCore>

namespace hooke {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat2 = Eigen::Matrix2d;
using Mat3 = Eigen::Matrix3d;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Mat8 = Eigen::Matrix<double, 8, 8>;
using Mat12 = Eigen::Matrix<double, 12, 12>;
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;
/// Row-major #rows x #cols arrays: node coordinates (#V x dim) and element connectivity (#E x nodes).
using RowMatX = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using RowMatXi = Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using SparseMatrix = Eigen::SparseMatrix<double>;
using Triplet = Eigen::Triplet<double>;

}  // namespace hooke
