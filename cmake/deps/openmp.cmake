# OpenMP (GCC's libgomp, part of the compiler): parallel element loops (core/element_schedule.cpp).
find_package(OpenMP REQUIRED COMPONENTS CXX)
