# CHOLMOD (Debian libsuitesparse-dev) has no CMake config and no pkg-config file; FindCHOLMOD.cmake locates it.
find_package(CHOLMOD REQUIRED)
