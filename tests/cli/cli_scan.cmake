# From a real closed surface (CGAL's elephant and head, Debian libcgal-demo) to a certified model on the command
# line: tetrahedralize with its report, calibrate an STL in one command with the meshing recorded in the model file,
# and an open scan refused with exit code 2, nothing written.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
include(${CMAKE_CURRENT_LIST_DIR}/run_hooke.cmake)
if(NOT EXISTS ${SCANS}/elephant.off)
  message(FATAL_ERROR "${SCANS}/elephant.off is missing: scripts/setup.sh installs libcgal-demo")
endif()

run_ok(convert mesh convert ${SCANS}/elephant.off ${OUT}/elephant.stl --binary)
run_ok(tetrahedralize mesh tetrahedralize ${OUT}/elephant.stl -o ${OUT}/elephant.msh)
if(NOT out MATCHES "surface nodes preserved" OR NOT out MATCHES "radius ratio min" OR NOT EXISTS ${OUT}/elephant.msh)
  message(FATAL_ERROR "mesh tetrahedralize did not report or write the mesh")
endif()

run_ok(calibrate calibrate ${OUT}/elephant.stl --young 3000 --poisson 0.45 --certify --certify-strain 0.001
       -o ${OUT}/m.json)
# A model file from a scan: its meshing names `mesher`, its method is the auto choice at nu = 0.45, and each of its
# three certificate cases is within 0.15 relative L2.
function(check_scan_model file mesher)
  file(READ ${file} json)
  string(JSON meshing GET "${json}" meshing)
  string(JSON method GET "${json}" method)
  string(JSON cases LENGTH "${json}" certificate)
  if(NOT meshing MATCHES "${mesher}" OR NOT meshing MATCHES "surface nodes preserved"
     OR NOT method STREQUAL "stiffness-fit-volume" OR NOT cases EQUAL 3)
    message(FATAL_ERROR "${file}: meshing '${meshing}', method ${method}, ${cases} certificate cases")
  endif()
  foreach(i RANGE 2)
    string(JSON l2 GET "${json}" certificate ${i} relative_l2)
    if(l2 GREATER 0.15)
      message(FATAL_ERROR "${file}: certificate case ${i}: relative L2 ${l2} > 0.15")
    endif()
  endforeach()
endfunction()
check_scan_model(${OUT}/m.json netgen)
# The same in one command with TetGen's program as the mesher: recorded in the model file, certified alike.
run_ok(calibrate_tetgen calibrate ${OUT}/elephant.stl --mesher tetgen --young 3000 --poisson 0.45 --certify
       --certify-strain 0.001 -o ${OUT}/m_tetgen.json)
check_scan_model(${OUT}/m_tetgen.json tetgen)
run_ok(simulate simulate ${OUT}/m.json --gravity --steps 50 --damping-mass 10 -o ${OUT}/sim)  # a model file as MESH

run_fails("open scan" "hole" ${OUT}/head.msh mesh tetrahedralize ${SCANS}/head.off -o ${OUT}/head.msh)
run_fails("both sizes" "not both" ${OUT}/x.msh mesh tetrahedralize ${SCANS}/elephant.off --size 0.1 --max-volume 1e-3
          -o ${OUT}/x.msh)
