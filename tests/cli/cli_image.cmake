# hooke mesh from-image and hooke calibrate on a label image (tests/CMakeLists.txt: cli_image): a real segmentation to
# tets with a region per label, a two-material model certified, and hostile images refused with exit code 2.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${HOOKE} mesh from-image ${IMAGE} --labels 2,3,4,5,6 -o ${OUT}/head.vtu
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "label 6     47201 voxels" OR NOT EXISTS ${OUT}/head.vtu)
  message(FATAL_ERROR "hooke mesh from-image failed: ${rc}")
endif()
# the soft classes 2, 3 and the stiff 4, 5, 6 (5 times E), certified against the FEM of the same regions
execute_process(COMMAND ${HOOKE} calibrate ${OUT}/head.vtu --method any-nu-tet --young 5000 --poisson 0.45
                        --material 4=25000,0.45 --material 5=25000,0.45 --material 6=25000,0.45 --certify
                        -o ${OUT}/head.json RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "region 6: E 25000 Pa" OR NOT EXISTS ${OUT}/head.json)
  message(FATAL_ERROR "hooke calibrate on the image's mesh failed: ${rc}")
endif()
# the image itself in place of a mesh (every label but 0), and hostile images: exit 2 with the file named
file(WRITE ${OUT}/text.nii.gz "not an image")
file(WRITE ${OUT}/flat.mha "ObjectType = Image\nNDims = 2\nDimSize = 4 4\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n")
foreach(bad text.nii.gz flat.mha missing.nrrd)
  execute_process(COMMAND ${HOOKE} mesh from-image ${OUT}/${bad} -o ${OUT}/bad.vtu RESULT_VARIABLE rc
                  ERROR_VARIABLE err OUTPUT_QUIET)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "${bad}" OR EXISTS ${OUT}/bad.vtu)
    message(FATAL_ERROR "${bad}: exit ${rc}, ${err}")
  endif()
endforeach()
