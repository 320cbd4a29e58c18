# CLI smoke test: fem on the committed cylinder at 12 % stretch, the VTU read back by hooke and by meshio
# (an independent reader of the VTK XML format); a bad Poisson ratio fails with exit code 2 and no output.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${HOOKE} fem ${MESHES}/cylinder.msh --young 14630 --poisson 0.3 --load stretch --strain 0.12
                        -o ${OUT}/cyl.vtu --csv ${OUT}/cyl.csv
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "hooke fem failed: ${rc}")
endif()
if(NOT out MATCHES "12.00 % of height")
  message(FATAL_ERROR "mean top displacement is not 12 % of the height")
endif()
execute_process(COMMAND ${HOOKE} mesh info ${OUT}/cyl.vtu RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "87")
  message(FATAL_ERROR "the written VTU does not read back: ${out}")
endif()
execute_process(COMMAND /usr/bin/python3 -c
  "import meshio,sys; m=meshio.read(sys.argv[1]); u=m.point_data['displacement']; assert len(m.points)==87 and u.shape==(87,3); assert abs(u[:,2].max())>1e-3; print('meshio read', len(m.points), 'points,', sum(len(c.data) for c in m.cells), 'cells')"
  ${OUT}/cyl.vtu RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "meshio cannot read the VTU")
endif()
execute_process(COMMAND ${HOOKE} fem ${MESHES}/cylinder.msh --young 14630 --poisson 0.5 --strain 0.1 -o ${OUT}/bad.vtu
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "Poisson" OR EXISTS ${OUT}/bad.vtu)
  message(FATAL_ERROR "nu = 0.5 must fail with exit code 2 and write nothing (got ${rc}: ${err})")
endif()
# Displacement control: a 40 % press of the Neo-Hookean cylinder reaches equilibrium, its top exactly 40 % down, and
# the force on the top is reported.
execute_process(COMMAND ${HOOKE} fem ${MESHES}/cylinder.msh --young 14630 --poisson 0.45 --material neohookean
                        --load compress --strain 0.4 --control displacement -o ${OUT}/press.vtu
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "40.00 % of height" OR NOT out MATCHES "force     on the top -?[0-9]")
  message(FATAL_ERROR "hooke fem --control displacement did not press 40 % and report the force (${rc})")
endif()

# hooke compare writes the VTU and the paper-style PNG (matplotlib through scripts/plot_figures.py).
execute_process(COMMAND ${HOOKE} compare ${MESHES}/cylinder.msh --young 14630 --poisson 0.25 --method lloyd-tet
                        --load shear --strain 0.12 -o ${OUT}/compare
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT}/compare/compare.vtu OR NOT EXISTS ${OUT}/compare/compare.png)
  message(FATAL_ERROR "hooke compare did not write compare.vtu and compare.png (${rc})")
endif()
file(READ ${OUT}/compare/compare.png png LIMIT 8 HEX)
if(NOT png STREQUAL "89504e470d0a1a0a")
  message(FATAL_ERROR "compare.png is not a PNG file")
endif()
# A malformed figure spec fails the plot script with exit code 2 and leaves no PNG.
file(WRITE ${OUT}/bad.json "{\"panels\": [{\"type\": \"pie\"}]}")
execute_process(COMMAND /usr/bin/python3 ${SCRIPTS}/plot_figures.py ${OUT}/bad.json RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR EXISTS ${OUT}/bad.png)
  message(FATAL_ERROR "a bad figure spec must fail with exit code 2 and write nothing (got ${rc}: ${err})")
endif()

# local/global with the Chebyshev global step runs from the command line; an iteration count below 1 is refused.
execute_process(COMMAND ${HOOKE} simulate ${MESHES}/cylinder.msh --young 14630 --poisson 0.25 --method lloyd-tet
                        --integrator local-global --global-solve chebyshev --iterations 7 --dt 0.001 --steps 20
                        --gravity -o ${OUT}/sim_cheb RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT}/sim_cheb/simulation.pvd)
  message(FATAL_ERROR "hooke simulate --global-solve chebyshev failed: ${rc}")
endif()
execute_process(COMMAND ${HOOKE} simulate ${MESHES}/cylinder.msh --young 14630 --poisson 0.25 --integrator local-global
                        --global-solve chebyshev --iterations 0 --steps 2 -o ${OUT}/sim_zero
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "--iterations 0 must fail with exit code 2 (got ${rc}: ${err})")
endif()

# A sphere tool pressed 3 mm into the top of the cylinder along a path table: tool_force.csv has a row per step with
# the body pushing the tool up, and a path without its columns is refused.
file(WRITE ${OUT}/path.csv "t,x,y,z\n0,0,0,0.0255\n0.05,0,0,0.022\n")
execute_process(COMMAND ${HOOKE} simulate ${MESHES}/cylinder.msh --young 14630 --poisson 0.45 --integrator implicit-euler
                        --dt 0.002 --steps 40 --damping-mass 40 --tool sphere:0.005 --tool-path ${OUT}/path.csv
                        -o ${OUT}/sim_tool RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT}/sim_tool/tool_force.csv OR NOT out MATCHES "tool      sphere:0.005: force on it")
  message(FATAL_ERROR "hooke simulate --tool failed: ${rc}")
endif()
file(STRINGS ${OUT}/sim_tool/tool_force.csv rows)
list(LENGTH rows count)
list(GET rows -1 last)
string(REPLACE "," ";" last "${last}")
list(GET last 3 fz)
if(NOT count EQUAL 41 OR NOT fz GREATER 0.01)
  message(FATAL_ERROR "tool_force.csv: ${count} lines, last fz ${fz} N")
endif()
# A mesh tool: the 10 mm sphere of sphere_surface.msh (its own coordinates, centred on its origin; edges rounded by
# 1 mm) pressed 3 mm into the top along a path.
file(WRITE ${OUT}/mesh_path.csv "t,x,y,z\n0,0,0,0.0305\n0.04,0,0,0.027\n")
execute_process(COMMAND ${HOOKE} simulate ${MESHES}/cylinder.msh --young 14630 --poisson 0.45 --steps 25 --dt 0.002
                        --damping-mass 40 --integrator implicit-euler --tool mesh:${MESHES}/sphere_surface.msh,0.001
                        --tool-path ${OUT}/mesh_path.csv -o ${OUT}/sim_mesh_tool RESULT_VARIABLE rc OUTPUT_VARIABLE out
                        ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "tool      mesh:[^ ]*sphere_surface.msh,0.001: force on it [-0-9.e]+, [-0-9.e]+, [0-9.e]+ N")
  message(FATAL_ERROR "hooke simulate --tool mesh: failed: ${rc}")
endif()
# The free cylinder under gravity on a floor 0.5 mm below it: it lands and the summary reports the floor's load; a
# floor through the body is refused.
execute_process(COMMAND ${HOOKE} simulate ${MESHES}/cylinder.msh --young 14630 --poisson 0.45 --integrator implicit-euler
                        --dt 0.002 --steps 50 --damping-mass 20 --free --gravity --obstacle plane:0,0,-0.0005
                        --friction 0.5 -o ${OUT}/sim_floor RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "obstacle  plane:0,0,-0.0005: force on it [-0-9.e]+, [-0-9.e]+, -[0-9.e]+ N"
   OR NOT out MATCHES "friction  coefficient 0.5, creep velocity")
  message(FATAL_ERROR "hooke simulate --obstacle failed: ${rc}")
endif()
# A mesh obstacle: a closed box (an OFF file) whose top is 0.5 mm below the free cylinder; it lands on it under gravity
# and the box carries it. The 10 mm sphere of sphere_surface.msh, where its file puts it (at the origin), is inside
# the body and refused.
file(WRITE ${OUT}/table.off "OFF\n8 12 0\n-0.05 -0.05 -0.0105\n0.05 -0.05 -0.0105\n-0.05 0.05 -0.0105\n0.05 0.05 -0.0105\n-0.05 -0.05 -0.0005\n0.05 -0.05 -0.0005\n-0.05 0.05 -0.0005\n0.05 0.05 -0.0005\n3 0 2 1\n3 1 2 3\n3 4 5 6\n3 5 7 6\n3 0 1 4\n3 1 5 4\n3 2 6 3\n3 3 6 7\n3 0 4 2\n3 2 4 6\n3 1 3 5\n3 3 7 5\n")
execute_process(COMMAND ${HOOKE} simulate ${MESHES}/cylinder.msh --young 14630 --poisson 0.45 --integrator implicit-euler
                        --dt 0.002 --steps 50 --damping-mass 20 --free --gravity --obstacle mesh:${OUT}/table.off
                        -o ${OUT}/sim_mesh_floor RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "obstacle  mesh:[^ ]*table.off: force on it [-0-9.e]+, [-0-9.e]+, -[0-9.e]+ N")
  message(FATAL_ERROR "hooke simulate --obstacle mesh: failed: ${rc}")
endif()
execute_process(COMMAND ${HOOKE} simulate ${MESHES}/cylinder.msh --young 14630 --poisson 0.45 --steps 2 --free
                        --obstacle mesh:${MESHES}/sphere_surface.msh -o ${OUT}/sim_mesh_inside RESULT_VARIABLE rc
                        ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "starts inside the obstacle mesh:")
  message(FATAL_ERROR "a mesh obstacle through the body must fail with exit code 2 (got ${rc}: ${err})")
endif()
execute_process(COMMAND ${HOOKE} simulate ${MESHES}/cylinder.msh --young 14630 --poisson 0.45 --steps 2 --free
                        --obstacle plane:0,0,0.01 -o ${OUT}/sim_bad_floor RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "starts inside the obstacle")
  message(FATAL_ERROR "a floor through the body must fail with exit code 2 (got ${rc}: ${err})")
endif()
execute_process(COMMAND ${HOOKE} simulate ${MESHES}/cylinder.msh --young 14630 --poisson 0.45 --steps 2 --free
                        --obstacle plane:0,0,-0.001 --friction -1 -o ${OUT}/sim_bad_friction RESULT_VARIABLE rc
                        ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "friction")
  message(FATAL_ERROR "a negative friction coefficient must fail with exit code 2 (got ${rc}: ${err})")
endif()
file(WRITE ${OUT}/bad_path.csv "time,x,y,z\n0,0,0,0.03\n")
execute_process(COMMAND ${HOOKE} simulate ${MESHES}/cylinder.msh --young 14630 --poisson 0.45 --steps 2
                        --tool sphere:0.005 --tool-path ${OUT}/bad_path.csv -o ${OUT}/sim_bad_tool
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "no column 't'" OR EXISTS ${OUT}/sim_bad_tool/simulation.pvd)
  message(FATAL_ERROR "a tool path without a t column must fail with exit code 2 (got ${rc}: ${err})")
endif()

# The surface model from the command line: simulate a closed surface with a probe, compare it with the FEM of
# its radially tetrahedralised volume.
execute_process(COMMAND ${HOOKE} simulate ${MESHES}/sphere_surface.msh --young 1000 --poisson 0.3 --method surface
                        --integrator symplectic-euler --dt 0.0005 --steps 40 --gravity --damping-mass 20
                        --probe-node 0 --probe-force 0,0,-0.002 -o ${OUT}/sim_surface
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "surface model" OR NOT EXISTS ${OUT}/sim_surface/simulation.pvd)
  message(FATAL_ERROR "hooke simulate --method surface failed: ${rc}")
endif()
execute_process(COMMAND ${HOOKE} compare ${MESHES}/../../tests/data/cube.off --young 3250 --poisson 0.3 --method surface
                        --scheme C --load compress --strain 0.02 -o ${OUT}/cmp_surface --no-figure
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "surface model \\(scheme C\\)" OR NOT EXISTS ${OUT}/cmp_surface/compare.vtu)
  message(FATAL_ERROR "hooke compare --method surface failed: ${rc}")
endif()
execute_process(COMMAND ${HOOKE} simulate ${MESHES}/sphere_surface.msh --young 1000 --poisson 0.3 --method surface
                        --centre 5,0,0 --steps 2 -o ${OUT}/sim_surface_outside RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "not star-shaped from it")
  message(FATAL_ERROR "a centre outside the body must fail with exit code 2 (got ${rc}: ${err})")
endif()
execute_process(COMMAND ${HOOKE} simulate ${MESHES}/cylinder.msh --young 1000 --poisson 0.3 --method surface --steps 2
                        -o ${OUT}/sim_surface_tets RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "closed triangle surface")
  message(FATAL_ERROR "a tet mesh given to the surface model must fail with exit code 2 (got ${rc}: ${err})")
endif()

# hooke simulate: the cylinder under gravity writes a ParaView series whose frames meshio reads back; an
# explicit step far beyond the stability limit fails with exit code 3 and leaves no series.
execute_process(COMMAND ${HOOKE} simulate ${MESHES}/cylinder.msh --young 14630 --poisson 0.25 --method lloyd-tet
                        --integrator implicit-euler --dt 0.001 --steps 50 --gravity -o ${OUT}/sim
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "ms/step median")
  message(FATAL_ERROR "hooke simulate failed: ${rc}")
endif()
execute_process(COMMAND /usr/bin/python3 -c
  "import sys, os, meshio, xml.etree.ElementTree as ET; d=os.path.dirname(sys.argv[1]); sets=ET.parse(sys.argv[1]).getroot().iter('DataSet'); fr=[(float(s.get('timestep')), meshio.read(os.path.join(d, s.get('file')))) for s in sets]; assert len(fr)==51 and abs(fr[-1][0]-0.05)<1e-12; u=fr[-1][1].point_data['displacement']; assert u.shape==(87,3) and u[:,2].min()<-1e-6; print('pvd:', len(fr), 'frames, last at', fr[-1][0], 's, min u_z', u[:,2].min())"
  ${OUT}/sim/simulation.pvd RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the simulation series does not read back")
endif()
execute_process(COMMAND ${HOOKE} simulate ${MESHES}/cylinder.msh --young 14630 --poisson 0.25 --integrator
                        symplectic-euler --dt 0.01 --steps 20 --gravity -o ${OUT}/sim_bad
                RESULT_VARIABLE rc ERROR_VARIABLE err)
file(GLOB sim_bad_frames ${OUT}/sim_bad/frames*)
if(NOT rc EQUAL 3 OR NOT err MATCHES "stability limit" OR EXISTS ${OUT}/sim_bad/simulation.pvd OR sim_bad_frames)
  message(FATAL_ERROR "an unstable explicit run must fail with exit code 3 and leave no series (got ${rc}: ${err})")
endif()

# hooke bench: the table on the 1 089-node cylinder (every run checked admissible), as Markdown and JSON; an unknown size is refused.
execute_process(COMMAND ${HOOKE} bench --sizes 1k --steps 3 --methods any-nu-tet,lloyd-tet --all -o ${OUT}/bench
                RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "local-global \\(chebyshev\\)" OR NOT out MATCHES "local-global \\(direct\\) on 1089 nodes \\(any-nu-tet\\) not applicable"
   OR NOT EXISTS ${OUT}/bench/bench.json)
  message(FATAL_ERROR "hooke bench failed: ${rc}")
endif()
file(READ ${OUT}/bench/bench.json bench_json)
string(JSON steps LENGTH "${bench_json}" steps)
# 12 rows for lloyd-tet, 10 for any-nu-tet (local-global needs springs only).
if(NOT steps EQUAL 22)
  message(FATAL_ERROR "hooke bench: expected 22 admissible integrator rows in bench.json, got ${steps}")
endif()
# The implicit-Euler and quasi-newton rows carry their error against the tightly converged step.
foreach(row 2 3 4 5 6 7 8)
  string(JSON name GET "${bench_json}" steps ${row} integrator)
  string(JSON error GET "${bench_json}" steps ${row} error_vs_converged)
  if(NOT name MATCHES "^(implicit-euler|quasi-newton)" OR error LESS 0 OR error GREATER 0.05)
    message(FATAL_ERROR "hooke bench: row ${row} is '${name}' with error ${error} against the converged step")
  endif()
endforeach()
# Without --all: the real-time row (quasi-newton (rest)) of the two default models, a progress line per row on
# standard error.
execute_process(COMMAND ${HOOKE} bench --sizes 1k --steps 3 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX MATCHALL "\\| 1089 \\| [a-z-]+ \\| [^|]+ \\|" rows "${out}")
string(REGEX MATCHALL "hooke bench: 1089 nodes, [a-z-]+, quasi-newton \\(rest\\): [0-9.]+ ms median" lines "${err}")
if(NOT rc EQUAL 0 OR NOT rows STREQUAL "| 1089 | any-nu-tet | quasi-newton (rest) |;| 1089 | stiffness-fit-volume | quasi-newton (rest) |"
   OR NOT lines MATCHES "any-nu-tet.*stiffness-fit-volume")
  message(FATAL_ERROR "hooke bench (default) failed (${rc}): rows '${rows}', progress '${lines}'\n${out}${err}")
endif()
# hooke bench --haptics: the multirate row on the 1 089-node cylinder, with its force error against the full-rate
# drag (a short drag, so that the test stays short); an unknown stiffness is refused.
execute_process(COMMAND ${HOOKE} bench --haptics --sizes 1k --ramp 0.3 --hold 0.1 -o ${OUT}/haptics
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "\\| 1089 \\|" OR NOT EXISTS ${OUT}/haptics/haptics.md)
  message(FATAL_ERROR "hooke bench --haptics failed (${rc}): ${out}${err}")
endif()
string(REGEX MATCH "\\| 1089 \\|[^\n]*" row "${out}")
# The cells of "| nodes | dt | step | models/s | Hz | period | tick | schedule | real time | held | reference |" with
# the empty cell before the first bar kept (CMP0007 NEW), so that the schedule's error is cell 8 and not the real-time
# one, which depends on the load of the machine.
cmake_policy(SET CMP0007 NEW)
string(REPLACE "|" ";" cells "${row}")
list(GET cells 8 schedule_error)
string(STRIP "${schedule_error}" schedule_error)
if(schedule_error GREATER 0.05)
  message(FATAL_ERROR "hooke bench --haptics: the schedule's force is ${schedule_error} off the full-rate drag: ${row}")
endif()
execute_process(COMMAND ${HOOKE} bench --haptics --sizes 1k --haptic-stiffness springy RESULT_VARIABLE rc)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "hooke bench --haptic-stiffness springy must fail with exit code 2 (got ${rc})")
endif()
execute_process(COMMAND ${HOOKE} bench --sizes 2k RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "hooke bench --sizes 2k must fail with exit code 2 (got ${rc}: ${err})")
endif()
# compare under contact: a sphere pressed 10 % into the top of the 87-node cylinder, the FEM beside the model; --tool
# with a load case is refused.
execute_process(COMMAND ${HOOKE} compare ${MESHES}/cylinder.msh --young 14630 --poisson 0.45 --method any-nu-tet
                        --tool sphere:0.005 --press 0.1 --press-steps 2 RESULT_VARIABLE rc OUTPUT_VARIABLE out
                        ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "worst     force error [0-9.e-]+, relative L2 [0-9.e-]+")
  message(FATAL_ERROR "hooke compare --tool failed: ${rc}")
endif()
execute_process(COMMAND ${HOOKE} compare ${MESHES}/cylinder.msh --young 14630 --poisson 0.45 --tool sphere:0.005
                        --strain 0.1 RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--tool compares under contact")
  message(FATAL_ERROR "compare --tool with --strain must fail with exit code 2 (got ${rc}: ${err})")
endif()
