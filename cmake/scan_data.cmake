# Real scanned surfaces no one on the project made, for the tests and benchmarks: CGAL's sample data (Debian
# libcgal-demo, installed by scripts/setup.sh; not committed), unpacked from the package's archive at configure
# time; nothing is downloaded. HOOKE_SCAN_DATA is the folder of the .off files.
set(HOOKE_SCAN_ARCHIVE /usr/share/doc/libcgal-dev/data.tar.gz)
set(HOOKE_SCAN_DATA ${PROJECT_BINARY_DIR}/scans/data/meshes)
if(EXISTS ${HOOKE_SCAN_DATA}/bunny00.off)
  # unpacked by an earlier configure
elseif(EXISTS ${HOOKE_SCAN_ARCHIVE})
  file(ARCHIVE_EXTRACT INPUT ${HOOKE_SCAN_ARCHIVE} DESTINATION ${PROJECT_BINARY_DIR}/scans
       PATTERNS data/meshes/femur.off data/meshes/head.off data/meshes/bones.off data/meshes/elephant.off
                data/meshes/bunny00.off)
else()
  message(WARNING "${HOOKE_SCAN_ARCHIVE} is missing (scripts/setup.sh installs libcgal-demo): the scan tests and benchmarks will fail")
endif()

