# hooke reproduce nu-range on a small grid (the cone, two methods, two nu, the linear regime): the report has a table
# per load with a number in every cell and picks any-nu-tet at tissue nu, where lloyd-tet is worse on every load.
file(REMOVE_RECURSE ${OUT})
include(${CMAKE_CURRENT_LIST_DIR}/run_hooke.cmake)
# Fails unless nu_range.md has, for every load, a table matching `pattern` with LOAD standing for the load.
function(require_load_tables what pattern)
  file(READ ${OUT}/nu_range.md md)
  foreach(load stretch compress shear)
    string(REPLACE "LOAD" "${load}" load_pattern "${pattern}")
    if(NOT md MATCHES "${load_pattern}")
      message(FATAL_ERROR "nu_range.md has no full ${load} table of ${what}:\n${md}")
    endif()
  endforeach()
endfunction()
run_ok(nu_range reproduce nu-range --nu 0.25,0.45 --methods lloyd-tet,any-nu-tet --study-meshes cone --large-strain 0
       --laws none --no-figures -o ${OUT})
if(NOT out MATCHES "pick tet, nu = 0.45: any-nu-tet, worst relative L2 0\\.[0-9]+ over 3 cases")
  message(FATAL_ERROR "nu-range did not pick any-nu-tet at nu = 0.45")
endif()
require_load_tables("the linear regime" "## cone, LOAD, 0.1 % strain, linear FEM\n\n[|] method [|] 0.25 [|] 0.45 [|]\n[|]---[|]---[|]---[|]\n[|] lloyd-tet [|] 0\\.[0-9]+ [|] 0\\.[0-9]+ [|]")
file(READ ${OUT}/nu_range.json json)
string(JSON rows LENGTH "${json}" rows)
if(NOT rows EQUAL 12 OR NOT EXISTS ${OUT}/figures/nu_range_linear_1.json)
  message(FATAL_ERROR "nu_range.json has ${rows} rows (12 expected) or the figure spec is missing")
endif()
# The method table `--method auto` picks from, in the form src/hooke/calibrate/method_table.inc holds it.
file(READ ${OUT}/method_table.inc table)
if(NOT table MATCHES "\{\"tet\", 0.45, \"any-nu-tet\", 0\.[0-9]+, 3\},")
  message(FATAL_ERROR "method_table.inc has no tet entry at nu = 0.45:\n${table}")
endif()
# A law regime (displacement control, Hookean and fitted terms) on the triangles in plane strain: a table per load
# with both numbers of both models, and a pick per regime.
file(REMOVE_RECURSE ${OUT})
run_ok(nu_range_law reproduce nu-range --nu 0.3 --triangle-methods any-nu-triangle --planes strain
       --study-meshes rectangle_tri --large-strain 0 --laws neohookean:0.2 --fit-refinements 1
       --no-figures -o ${OUT})
if(NOT out MATCHES "pick triangle plane-strain, nu = 0.3, neohookean FEM at 20 % strain, displacement control: any-nu-triangle( fitted)?, worst of relative L2 and force error 0\\.[0-9]+ over 3 cases")
  message(FATAL_ERROR "nu-range printed no pick for the law regime:\n${out}")
endif()
require_load_tables("the law regime" "## rectangle_tri [(]plane strain[)], LOAD, neohookean FEM at 20 % strain, displacement control\n\n[^\n]*\n\n[|] model [|] 0.3 [|]\n[|]---[|]---[|]\n[|] any-nu-triangle [|] 0\\.[0-9]+ / 0\\.[0-9]+ [|]\n[|] any-nu-triangle fitted [|] 0\\.[0-9]+ / 0\\.[0-9]+ [(]-?[0-9.]+, -?[0-9.]+[)] [|]")
file(REMOVE_RECURSE ${OUT})
run_fails(nu_range_bad_law "is not LAW:STRAIN" ${OUT}/nu_range.md reproduce nu-range --laws neohookean
          --study-meshes rectangle_tri -o ${OUT})
