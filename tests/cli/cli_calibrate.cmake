# hooke calibrate writes the model (JSON with its certificate, VTU and CSV exports); simulate and compare run it
# from the file alone and give what --method gives; bad model files fail with exit code 2 naming the entry.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
set(mesh ${MESHES}/cylinder_hole.msh)

include(${CMAKE_CURRENT_LIST_DIR}/run_hooke.cmake)

# The acceptance command of the model-file issue.
run_ok(calibrate calibrate ${mesh} --young 14630 --poisson 0.3 --method lloyd-tet --certify -o ${OUT}/m.json)
if(NOT out MATCHES "certificate" OR NOT out MATCHES "shear +1 % strain: max" OR NOT EXISTS ${OUT}/m.json)
  message(FATAL_ERROR "calibrate --certify did not print the certificate or write m.json")
endif()
string(REGEX MATCH "shear +1 % strain: max [^\n]*relative L2 ([0-9.e-]+)" _ "${out}")
set(certified_shear ${CMAKE_MATCH_1})
file(READ ${OUT}/m.json json)
string(JSON version GET "${json}" schema_version)
string(JSON springs LENGTH "${json}" springs)
string(JSON cases LENGTH "${json}" certificate)
string(JSON warning GET "${json}" warnings 0)
if(NOT version EQUAL 1 OR springs LESS 1000 OR NOT cases EQUAL 3 OR NOT warning MATCHES "nu = 1/4")
  message(FATAL_ERROR "m.json: schema ${version}, ${springs} springs, ${cases} certificate cases, warning '${warning}'")
endif()

# The model from the file alone, and the same method from the mesh: the same trajectory.
set(sim --integrator implicit-euler --dt 0.001 --steps 20 --gravity --damping-mass 5 --every 20)
run_ok("simulate --model" simulate --model ${OUT}/m.json ${sim} -o ${OUT}/sim_model)
run_ok("simulate --method" simulate ${mesh} --young 14630 --poisson 0.3 --method lloyd-tet ${sim} -o ${OUT}/sim_method)
file(GLOB model_frame ${OUT}/sim_model/frames-*/frame_1.vtu)
file(GLOB method_frame ${OUT}/sim_method/frames-*/frame_1.vtu)
execute_process(COMMAND /usr/bin/python3 -c
  "import sys, meshio, numpy as np; a=meshio.read(sys.argv[1]).point_data['displacement']; b=meshio.read(sys.argv[2]).point_data['displacement']; d=np.abs(a-b).max(); print('max difference', d, 'of', np.abs(a).max()); assert np.abs(a).max()>1e-6 and d<=1e-12"
  ${model_frame} ${method_frame}
  RESULT_VARIABLE rc OUTPUT_VARIABLE pyout ERROR_VARIABLE pyerr)
message("${pyout}${pyerr}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "simulate --model and --method give different trajectories")
endif()

# compare --model measures what the certificate says.
run_ok("compare --model" compare --model ${OUT}/m.json --load shear --strain 0.01)
string(REGEX MATCH "relative L2 ([0-9.e-]+)" _ "${out}")
if(NOT CMAKE_MATCH_1 STREQUAL certified_shear)
  message(FATAL_ERROR "compare --model gives relative L2 ${CMAKE_MATCH_1}, the certificate ${certified_shear}")
endif()
run_ok("compare --model with its mesh" compare ${mesh} --model ${OUT}/m.json --load stretch --strain 0.01)

# Exports for ParaView and spreadsheets.
run_ok("calibrate .vtu" calibrate ${mesh} --young 14630 --poisson 0.3 -o ${OUT}/m.vtu)
run_ok("calibrate .csv" calibrate ${mesh} --young 14630 --poisson 0.3 -o ${OUT}/m.csv)
execute_process(COMMAND /usr/bin/python3 -c
  "import sys, csv, meshio; m=meshio.read(sys.argv[1]); k=m.cell_data['stiffness'][0]; rows=list(csv.DictReader(open(sys.argv[2]))); assert len(rows)==len(k) and abs(float(rows[0]['stiffness_n_per_m'])-k[0])<=1e-12*abs(k[0]); e=meshio.read(sys.argv[3]); assert len(e.cells[0].data)>1000; print(len(k), 'springs in VTU and CSV,', len(e.cells[0].data), 'tets')"
  ${OUT}/m.vtu ${OUT}/m.csv ${OUT}/m_elements.vtu RESULT_VARIABLE rc OUTPUT_VARIABLE pyout ERROR_VARIABLE pyerr)
message("${pyout}${pyerr}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the VTU / CSV exports do not read back")
endif()

# Bad input.
string(REPLACE "\"springs\": [\n    [" "\"springs\": [\n    [0, 1, -5, 0.01],\n    [" bad "${json}")
file(WRITE ${OUT}/bad.json "${bad}")
run_fails("a negative stiffness" "bad.json: springs\\[0\\]: stiffness" "" simulate --model ${OUT}/bad.json --steps 2
          -o ${OUT}/sim_bad)
run_fails("a model on another mesh" "do not match" "" simulate ${MESHES}/cylinder.msh --model ${OUT}/m.json --steps 2
          -o ${OUT}/sim_other)
run_fails("--model with --young" "drop --young" "" compare --model ${OUT}/m.json --young 100 --strain 0.01)
run_fails("an unknown extension" "extension" ${OUT}/m.txt calibrate ${mesh} --young 14630 --poisson 0.3 -o ${OUT}/m.txt)
run_fails("an unknown method" "unknown method 'springy'" ${OUT}/x.json calibrate ${mesh} --young 1 --poisson 0.3
          --method springy -o ${OUT}/x.json)
