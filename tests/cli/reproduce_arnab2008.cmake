# hooke reproduce arnab2008 end to end: the report, its JSON and the figures are written, and the Young's modulus
# re-extracted from every cube of Table 1 is within 2 % of the input (the paper: 4.5 %).
include(${CMAKE_CURRENT_LIST_DIR}/reproduce_common.cmake)
run_reproduce(arnab2008 arnab2008.md arnab2008.json figures/fig08_refinement.png figures/fig09_gravity.png
              figures/fig10_volume_deviation.png figures/fig11_weights.png figures/fig12_shear.png)
file(READ ${OUT}/arnab2008.json json)
string(JSON rows LENGTH "${json}" table1)
if(NOT rows EQUAL 6)
  message(FATAL_ERROR "Table 1 has ${rows} rows, not 6")
endif()
math(EXPR last "${rows} - 1")
foreach(i RANGE ${last})
  string(JSON dev GET "${json}" table1 ${i} deviation_percent)
  if(dev GREATER 2.0 OR dev LESS -2.0)
    message(FATAL_ERROR "Table 1 row ${i}: re-extracted E deviates by ${dev} %")
  endif()
endforeach()
string(JSON rows2 LENGTH "${json}" table2)
if(NOT rows2 EQUAL 4)
  message(FATAL_ERROR "Table 2 has ${rows2} rows, not 4")
endif()
require_in_report(arnab2008.md "Table 1" "Table 2" "| 2402 nodes | 3250 Pa | 3110 Pa |" "sphere 1002" "Fig. 9" "Fig. 11"
                  "figures/fig12_shear.png")
