# cmake --install: headers, the static library hooke::hooke, the CLI, a CMake package config and a pkg-config file.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(HOOKE_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/hooke)

install(TARGETS hooke_core EXPORT hookeTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS hooke_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/hooke DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
install(FILES ${PROJECT_BINARY_DIR}/generated/hooke/core/version.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hooke/core)
install(EXPORT hookeTargets NAMESPACE hooke:: DESTINATION ${HOOKE_CMAKE_DIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/package/hookeConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/package/hookeConfig.cmake INSTALL_DESTINATION ${HOOKE_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/package/hookeConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/package/hookeConfig.cmake ${PROJECT_BINARY_DIR}/package/hookeConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/deps/FindCHOLMOD.cmake ${PROJECT_SOURCE_DIR}/cmake/deps/FindNglib.cmake
        DESTINATION ${HOOKE_CMAKE_DIR})

# pkg-config: the static library needs CHOLMOD, nglib (with its run path) and OpenMP at every link, so they are in Libs, not Libs.private.
set(HOOKE_PC_LIBS "${CHOLMOD_LIBRARY} ${SUITESPARSECONFIG_LIBRARY} ${NGLIB_LIBRARY} ${NGLIB_MESH_LIBRARY} ${NGLIB_CORE_LIBRARY} -Wl,-rpath,${NGLIB_LIBRARY_DIR}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/package/hooke.pc.in ${PROJECT_BINARY_DIR}/package/hooke.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/package/hooke.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
