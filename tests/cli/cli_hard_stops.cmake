# Issue 16 items 7 and 8: every numeric option is finite, every result is finite before it is written, and the
# output folder is a writable folder. Each case must exit with the code given and write nothing.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
set(mesh ${MESHES}/cylinder.msh)
set(material --young 14630 --poisson 0.3)

# expect(NAME CODE PATTERN ARGS...): hooke ARGS exits with CODE and its error output matches PATTERN.
function(expect name code pattern)
  execute_process(COMMAND ${HOOKE} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL ${code} OR NOT err MATCHES "${pattern}")
    message(FATAL_ERROR "${name}: expected exit ${code} and '${pattern}', got ${rc}: ${out}${err}")
  endif()
  message("${name}: exit ${rc}: ${err}")
endfunction()

# A traction of 1e200 Pa overflows the displacement: exit 3 naming it, and no VTU with inf in it.
expect("fem --traction 1e200" 3 "overflowed" fem ${mesh} ${material} --traction 1e200 -o ${OUT}/inf.vtu)
if(EXISTS ${OUT}/inf.vtu)
  message(FATAL_ERROR "fem wrote a VTU with non-finite values")
endif()
# NaN and infinite options are refused by name before anything runs.
expect("--damping-stiffness nan" 2 "--damping-stiffness must be a finite number" simulate ${mesh} ${material}
       --damping-stiffness nan -o ${OUT}/nan)
expect("--strain nan" 2 "--strain must be a finite number" fem ${mesh} ${material} --strain nan -o ${OUT}/s.vtu)
expect("--probe-force nan" 2 "--probe-force must be a finite number" simulate ${mesh} ${material} --probe-node 3
       --probe-force nan,0,0 -o ${OUT}/nan)
expect("--young inf" 2 "--young must be a finite number" calibrate ${mesh} --young inf --poisson 0.3 -o ${OUT}/m.json)
# compare refuses a strain that is not positive, as fem does.
expect("compare --strain 0" 2 "--strain must be > 0" compare ${mesh} ${material} --strain 0)
expect("compare --strain -5" 2 "--strain must be > 0" compare ${mesh} ${material} --strain -5)
# A force of 1e300 N made Newton's force scale infinite, so every step "converged" at iteration 0.
expect("--probe-force 1e300" 3 "step 1" simulate ${mesh} ${material} --probe-node 3 --probe-force 0,0,1e300
       --steps 5 -o ${OUT}/huge)
# Steps that end above the Newton tolerance fail the run (or are allowed by name).
expect("unconverged" 3 "above the Newton tolerance" simulate ${mesh} ${material} --integrator implicit-euler
       --newton-iterations 1 --steps 3 --gravity -o ${OUT}/unconverged)
expect("quasi-newton over budget" 3 "above the Newton tolerance" simulate ${mesh} ${material} --qn-iterations 1
       --qn-tolerance 1e-9 --steps 3 --gravity -o ${OUT}/unconverged)
execute_process(COMMAND ${HOOKE} simulate ${mesh} ${material} --integrator implicit-euler --newton-iterations 1
                        --steps 3 --gravity
                        --allow-unconverged -o ${OUT}/allowed RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "3 steps ended above the Newton tolerance")
  message(FATAL_ERROR "--allow-unconverged: expected exit 0 and a warning, got ${rc}: ${out}")
endif()
foreach(dir nan huge unconverged)
  if(EXISTS ${OUT}/${dir})
    message(FATAL_ERROR "a failed simulate left its output folder ${OUT}/${dir}")
  endif()
endforeach()
# -o naming a file: an IoError (exit 2), not a raw filesystem error (exit 4).
file(WRITE ${OUT}/a_file "not a folder\n")
expect("simulate -o FILE" 2 "is a file" simulate ${mesh} ${material} --steps 2 -o ${OUT}/a_file)
expect("compare -o FILE" 2 "is a file" compare ${mesh} ${material} --strain 0.01 --no-figure -o ${OUT}/a_file)

# Item 9: a command's outputs are whole or absent.
# fem: a --csv that cannot be written used to leave the VTU behind.
expect("fem --csv into a file" 2 "is a file" fem ${mesh} ${material} --strain 0.01 -o ${OUT}/both.vtu
       --csv ${OUT}/a_file/both.csv)
if(EXISTS ${OUT}/both.vtu)
  message(FATAL_ERROR "fem wrote the VTU although the CSV failed")
endif()
# compare: a figure that cannot be drawn used to leave compare.vtu and compare.json behind.
execute_process(COMMAND ${CMAKE_COMMAND} -E env HOOKE_PLOT_SCRIPT=${OUT}/no_such_script.py ${HOOKE} compare ${mesh} ${material}
                        --strain 0.01 -o ${OUT}/cmp RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc EQUAL 0 OR EXISTS ${OUT}/cmp)
  message(FATAL_ERROR "compare with a failing figure: expected a failure and no folder, got ${rc}: ${err}")
endif()
# mesh convert to TetGen: an .ele that cannot be written used to leave the .node behind.
file(MAKE_DIRECTORY ${OUT}/t.ele)
expect("mesh convert onto a folder" 2 "cannot replace" mesh convert ${mesh} ${OUT}/t.ele)
file(GLOB tetgen_left ${OUT}/t.node ${OUT}/t.face ${OUT}/t.staging*)
if(tetgen_left)
  message(FATAL_ERROR "mesh convert left ${tetgen_left}")
endif()
