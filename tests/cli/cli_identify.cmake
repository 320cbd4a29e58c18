# hooke identify: from hooke's FEM (and back from the reference files it wrote), a model file that compare runs;
# bad input exits 2 naming the problem and writes nothing.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
set(mesh ${MESHES}/cylinder.msh)

include(${CMAKE_CURRENT_LIST_DIR}/run_hooke.cmake)

run_ok(identify identify ${mesh} --young 14630 --poisson 0.45 --objective positions --iterations 5 --held-out 2
       --report ${OUT}/report.json --write-reference ${OUT}/cases -o ${OUT}/id.json)
if(NOT out MATCHES "RMS training" OR NOT EXISTS ${OUT}/id.json OR NOT EXISTS ${OUT}/cases/case_14.vtu)
  message(FATAL_ERROR "identify did not report, write the model or the 14 reference files")
endif()
file(READ ${OUT}/report.json report)
string(JSON held GET "${report}" held_out_relative_l2_rms)
string(JSON analytic GET "${report}" analytic_held_out_relative_l2_rms)
if(NOT held LESS analytic)
  message(FATAL_ERROR "held-out error ${held} is not below the analytic model's ${analytic}")
endif()
file(READ ${OUT}/id.json json)
string(JSON method GET "${json}" method)
if(NOT method STREQUAL "identified")
  message(FATAL_ERROR "id.json: method '${method}'")
endif()
run_ok(compare compare --model ${OUT}/id.json --load shear --strain 0.001 -o ${OUT}/compare)

# One factor on stiffness-fit (Eq. 1 with theta = c): better than stiffness-fit itself on the held-out cases. Since
# stiffness-fit already carries the factor fitted under self-weight (calibrate/stiffness_scale.hpp), the one fitted to
# these load cases stays within 10 % of 1.
run_ok(identify_scale identify ${mesh} --young 14630 --poisson 0.25 --params scale --compare stiffness-fit --held-out 2
       --report ${OUT}/scale.json -o ${OUT}/scaled.json)
file(READ ${OUT}/scale.json report)
string(JSON c GET "${report}" scale_factor)
string(JSON held GET "${report}" held_out_relative_l2_rms)
string(JSON analytic GET "${report}" analytic_held_out_relative_l2_rms)
if(NOT out MATCHES "one factor on stiffness-fit" OR NOT c GREATER 0.9 OR NOT c LESS 1.1 OR NOT held LESS analytic)
  message(FATAL_ERROR "scale: c = ${c}, held out ${held} against stiffness-fit's ${analytic}")
endif()
message("scale: c = ${c}, held out ${held} against stiffness-fit's ${analytic}")
run_fails(scale_unknown_start "unknown calibration method" ${OUT}/y.json identify ${MESHES}/rectangle_tri.msh --young 14630 --poisson 0.3
          --params scale --compare no-such-method -o ${OUT}/y.json)

# From the files it wrote: the first 12 to fit, the last 2 held out.
set(files "")
foreach(i RANGE 1 12)
  list(APPEND files ${OUT}/cases/case_${i}.vtu)
endforeach()
run_ok(identify_files identify ${mesh} --young 14630 --poisson 0.45 --params springs --reference ${files}
       --held-out-reference ${OUT}/cases/case_13.vtu ${OUT}/cases/case_14.vtu -o ${OUT}/from_files.csv)
if(NOT out MATCHES "reference files" OR NOT out MATCHES "case_14.vtu +held out" OR NOT EXISTS ${OUT}/from_files.csv)
  message(FATAL_ERROR "identify from files did not fit 12 and hold out 2")
endif()

run_fails(wrong_mesh "case_1.vtu: .* points where the mesh has" ${OUT}/x.json identify ${MESHES}/cone.msh --young 14630
          --poisson 0.45 --reference ${OUT}/cases/case_1.vtu -o ${OUT}/x.json)
run_fails(volume_on_triangles "need a tet mesh" ${OUT}/x.json identify ${MESHES}/rectangle_tri.msh --young 14630
          --poisson 0.3 --params springs+volume -o ${OUT}/x.json)
run_fails(bad_objective "unknown identification objective 'energy'" ${OUT}/x.json identify ${mesh} --young 14630
          --poisson 0.3 --objective energy -o ${OUT}/x.json)
run_fails(bad_strain "strain must be positive" ${OUT}/x.json identify ${mesh} --young 14630 --poisson 0.3
          --strain -1 -o ${OUT}/x.json)
run_fails(nu_half "oisson" ${OUT}/x.json identify ${mesh} --young 14630 --poisson 0.5 -o ${OUT}/x.json)
run_fails(bad_tolerance "tolerance must be in \\(0, 1\\)" ${OUT}/x.json identify ${mesh} --young 14630 --poisson 0.3
          --tolerance 0 -o ${OUT}/x.json)

# Below nu = 1/4, --negative-volume lets the force fit take k_V < 0, and the report says which options ran.
run_ok(identify_negative identify ${mesh} --young 14630 --poisson 0.1 --held-out 0 --negative-volume --tolerance 1e-2
       --report ${OUT}/negative.json -o ${OUT}/negative_model.json)
file(READ ${OUT}/negative.json report)
string(JSON negative GET "${report}" negative_volume)
string(JSON tolerance GET "${report}" tolerance)
if(NOT negative OR NOT tolerance EQUAL 0.01)
  message(FATAL_ERROR "negative.json: negative_volume ${negative}, tolerance ${tolerance}")
endif()
file(READ ${OUT}/negative_model.json json)
string(JSON terms LENGTH "${json}" volume_terms)
set(negatives 0)
math(EXPR last "${terms} - 1")
foreach(t RANGE ${last})
  string(JSON kv GET "${json}" volume_terms ${t} 4)
  if(kv LESS 0)
    math(EXPR negatives "${negatives} + 1")
  endif()
endforeach()
if(negatives EQUAL 0)
  message(FATAL_ERROR "--negative-volume at nu = 0.1: no negative volume term in ${terms}")
endif()

# Displacement control: the loaded nodes held and moved, the force on them measured; every case reports a force error
# in the table and the report, and the written reference files mark the held nodes.
run_ok(identify_pressed identify ${mesh} --young 14630 --poisson 0.45 --law neohookean --strain 0.2
       --control displacement --held-out 1 --iterations 5 --report ${OUT}/pressed.json
       --write-reference ${OUT}/pressed_cases -o ${OUT}/pressed_model.json)
if(NOT out MATCHES "force error: identified, analytic")
  message(FATAL_ERROR "identify --control displacement printed no force errors:\n${out}")
endif()
file(READ ${OUT}/pressed.json report)
string(JSON force GET "${report}" cases 0 identified_force_error)
if(force LESS 0 OR force GREATER 0.5)
  message(FATAL_ERROR "pressed.json: the first case's force error is ${force}")
endif()
file(READ ${OUT}/pressed_cases/case_1.vtu vtu)
if(NOT vtu MATCHES "Name=\"prescribed\"")
  message(FATAL_ERROR "the written reference case has no 'prescribed' array")
endif()
run_fails(control_with_files "applies to FEM references" ${OUT}/x.json identify ${mesh} --young 14630 --poisson 0.45
          --reference ${OUT}/pressed_cases/case_1.vtu --control displacement -o ${OUT}/x.json)
# The written cases are data like any measurement: identified from the files, the held nodes are held again.
run_ok(identify_pressed_files identify ${mesh} --young 14630 --poisson 0.45 --objective forces
       --reference ${OUT}/pressed_cases/case_1.vtu ${OUT}/pressed_cases/case_2.vtu ${OUT}/pressed_cases/case_3.vtu
       --report ${OUT}/pressed_files.json -o ${OUT}/x.json)
file(READ ${OUT}/pressed_files.json report)
string(JSON force GET "${report}" cases 0 identified_force_error)
if(force LESS 0)
  message(FATAL_ERROR "cases read from files lost their held nodes (force error ${force})")
endif()
