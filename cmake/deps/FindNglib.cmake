# Locates Netgen's nglib (Debian libnglib-dev, LGPL-2.1) and defines the imported target Nglib::Nglib. Debian puts
# the libraries in a private directory (lib/<arch>/netgen) with no pkg-config file; its NetgenConfig.cmake pulls in
# MPI, OpenCASCADE and Tk, which hooke does not need, so the two libraries hooke calls are found directly:
# libnglib (the C interface), libmesh and libngcore (Netgen's message switches and streams). Linked dynamically: hooke stays MIT.
find_path(NGLIB_INCLUDE_DIR nglib.h PATH_SUFFIXES netgen)
find_library(NGLIB_LIBRARY nglib PATH_SUFFIXES netgen)
find_library(NGLIB_MESH_LIBRARY mesh PATH_SUFFIXES netgen)
find_library(NGLIB_CORE_LIBRARY ngcore PATH_SUFFIXES netgen)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Nglib REQUIRED_VARS NGLIB_INCLUDE_DIR NGLIB_LIBRARY NGLIB_MESH_LIBRARY NGLIB_CORE_LIBRARY)
if(Nglib_FOUND AND NOT TARGET Nglib::Nglib)
  get_filename_component(NGLIB_LIBRARY_DIR "${NGLIB_LIBRARY}" DIRECTORY)
  add_library(Nglib::Nglib UNKNOWN IMPORTED)
  # The private directory is not on the loader's path: every program linking hooke gets it as a run path.
  set_target_properties(Nglib::Nglib PROPERTIES
    IMPORTED_LOCATION "${NGLIB_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${NGLIB_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${NGLIB_MESH_LIBRARY};${NGLIB_CORE_LIBRARY}"
    INTERFACE_LINK_OPTIONS "LINKER:-rpath,${NGLIB_LIBRARY_DIR}")
endif()
mark_as_advanced(NGLIB_INCLUDE_DIR NGLIB_LIBRARY NGLIB_MESH_LIBRARY NGLIB_CORE_LIBRARY)
