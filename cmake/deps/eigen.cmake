# Eigen 3.4 (Debian libeigen3-dev): dense and sparse linear algebra.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
