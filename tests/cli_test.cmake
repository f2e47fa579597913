# Runs the quadtri CLI and checks exit codes, messages and outputs.
#   cmake -DQUADTRI=<exe> -DMESHES=<tests/meshes> -DWORK=<scratch dir> -P cli_test.cmake
foreach(var QUADTRI MESHES WORK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "cli_test.cmake needs -D${var}=...")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

# Runs that create a Vulkan device (refine --evaluator vulkan, demo) use VULKAN_PREFIX: in the
# sanitizer build LeakSanitizer reports 128 bytes from lavapipe once the loader has unloaded the
# driver at exit (memory its globals still reach; an unnamed module, so no suppression can match
# it). Only leak checking is off for those runs; address and undefined-behaviour checks stay on.
set(VULKAN_PREFIX ${CMAKE_COMMAND} -E env ASAN_OPTIONS=detect_leaks=0:abort_on_error=1)

# run(<expected exit code> <args>...): runs quadtri, leaves OUT, ERR and the command line in CMD.
macro(run expected)
  set(CMD "quadtri ${ARGN}")
  execute_process(COMMAND ${RUN_PREFIX} "${QUADTRI}" ${ARGN} RESULT_VARIABLE RC OUTPUT_VARIABLE OUT ERROR_VARIABLE ERR
                  TIMEOUT 120)
  if(NOT "${RC}" STREQUAL "${expected}")
    message(FATAL_ERROR "${CMD}: exit status '${RC}', expected ${expected}\nstdout:\n${OUT}\nstderr:\n${ERR}")
  endif()
  if(NOT "${expected}" STREQUAL "0" AND NOT ERR MATCHES "^quadtri: ")
    message(FATAL_ERROR "${CMD}: stderr does not start with 'quadtri: ':\n${ERR}")
  endif()
endmacro()

function(expect_contains text needle)
  string(FIND "${text}" "${needle}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "${CMD}: expected '${needle}' in:\n${text}")
  endif()
endfunction()

# Number of lines of `file` starting with `prefix` (e.g. "v ").
function(count_lines file prefix outvar)
  file(STRINGS "${file}" lines REGEX "^${prefix}")
  list(LENGTH lines n)
  set(${outvar} ${n} PARENT_SCOPE)
endfunction()

function(expect_equal what actual expected)
  if(NOT "${actual}" STREQUAL "${expected}")
    message(FATAL_ERROR "${CMD}: ${what} is '${actual}', expected '${expected}'")
  endif()
endfunction()

set(CYLINDER "${MESHES}/mixed/cylinder_capped.obj")

# --- success paths ---------------------------------------------------------------------------
run(0 --help)
expect_contains("${OUT}" "refine")

# cylinder_capped: 34 vertices, 40 faces (24 quads, 16 triangles), 72 edges, closed. Level 1 adds a
# point per edge and per quad: 34 + 72 + 24 = 130 vertices, 160 faces (96 quads), 288 edges;
# level 2: 130 + 288 + 96 = 514 vertices, 640 faces.
count_lines("${CYLINDER}" "v " input_vertices)
expect_equal("vertices of the input" "${input_vertices}" 34)

run(0 refine "${CYLINDER}" --level 2 -o "${WORK}/cylinder_l2.obj")
expect_contains("${OUT}" "514 vertices")
count_lines("${WORK}/cylinder_l2.obj" "v " vertices)
count_lines("${WORK}/cylinder_l2.obj" "f " faces)
expect_equal("'v' lines of level 2" "${vertices}" 514)
expect_equal("'f' lines of level 2" "${faces}" 640)

run(0 info "${CYLINDER}" --level 2)
expect_contains("${OUT}" "vertices 34, faces 40, edges 72")
if(NOT OUT MATCHES "\n\\| 2 \\| ([0-9]+) \\| ([0-9]+) \\|")
  message(FATAL_ERROR "${CMD}: no level-2 row in:\n${OUT}")
endif()
expect_equal("vertices info reports for level 2" "${CMAKE_MATCH_1}" "${vertices}")
expect_equal("faces info reports for level 2" "${CMAKE_MATCH_2}" "${faces}")

# Level 0 writes the input back; the bilinear scheme and boundary flags are accepted.
run(0 refine "${CYLINDER}" --level 0 -o "${WORK}/cylinder_l0.obj")
count_lines("${WORK}/cylinder_l0.obj" "v " vertices)
expect_equal("'v' lines of level 0" "${vertices}" 34)
run(0 refine "${CYLINDER}" --level 1 --scheme bilinear --boundary edge-and-corner -o "${WORK}/cylinder_bl.obj")
count_lines("${WORK}/cylinder_bl.obj" "v " vertices)
expect_equal("'v' lines of bilinear level 1" "${vertices}" 130)
run(0 refine "${CYLINDER}" --level 1 --scheme catmark-butterfly -o "${WORK}/cylinder_cb.obj")
count_lines("${WORK}/cylinder_cb.obj" "v " vertices)
expect_equal("'v' lines of catmark-butterfly level 1" "${vertices}" 130)
run(0 info "${CYLINDER}" --level 1 --scheme catmark-butterfly)
expect_contains("${OUT}" "scheme catmark-butterfly")

set(RUN_PREFIX ${VULKAN_PREFIX})
run(0 demo "${CYLINDER}" --levels 2 --out-dir "${WORK}/demo")
unset(RUN_PREFIX)
expect_contains("${OUT}" "| analyzer ms |")
foreach(L 1 2)
  if(NOT EXISTS "${WORK}/demo/cylinder_capped_level${L}.obj")
    message(FATAL_ERROR "${CMD}: did not write ${WORK}/demo/cylinder_capped_level${L}.obj")
  endif()
endforeach()

# --- errors: exit status 2, a "quadtri: " message, never a crash ------------------------------
run(2 refine "${WORK}/no_such_mesh.obj" --level 1 -o "${WORK}/x.obj")
expect_contains("${ERR}" "no_such_mesh.obj: cannot open")

file(WRITE "${WORK}/bad.obj" "v 0 0 0\nv 1 0 0\nf 1 2 7\n")
run(2 refine "${WORK}/bad.obj" --level 1 -o "${WORK}/x.obj")
expect_contains("${ERR}" "bad.obj:3:")
run(2 info "${WORK}/bad.obj")
expect_contains("${ERR}" "bad.obj:3:")

file(WRITE "${WORK}/badnum.obj" "v 0 0 0\nv 1 zero 0\n")
run(2 info "${WORK}/badnum.obj")
expect_contains("${ERR}" "badnum.obj:2:")

file(WRITE "${WORK}/repeated.obj" "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4 3\n")
# A vertex met again further on pinches the face: it is read as its loops (here none with 3
# corners: left out), with a warning naming the line.
run(0 refine "${WORK}/repeated.obj" --level 1 -o "${WORK}/x.obj")
expect_contains("${ERR}" "repeated.obj:6: ")
expect_contains("${ERR}" "appears again further on")

# A corner repeating the previous one is a collapsed edge: the quad is read as a triangle.
file(WRITE "${WORK}/collapsed.obj" "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 3 4\n")
run(0 info "${WORK}/collapsed.obj")
expect_contains("${OUT}" "3-gon 2")

# A crease tag on two vertices that share no edge is warned about (naming the tag's line) and
# ignored, as OpenSubdiv does.
file(WRITE "${WORK}/crease.obj" "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\nt crease 2/1/0 1 3 2.0\n")
run(0 info "${WORK}/crease.obj")
expect_contains("${ERR}" "warning: ${WORK}/crease.obj:7: crease 0: vertices 1, 3 are not an edge of the mesh; crease ignored")

run(2 refine "${CYLINDER}" --level 1 --scheme catmark -o "${WORK}/x.obj")
expect_contains("${ERR}" "catmark")
run(2 refine "${CYLINDER}" --level 1 --boundary sometimes -o "${WORK}/x.obj")
run(2 refine "${CYLINDER}" --level -1 -o "${WORK}/x.obj")
run(2 refine "${CYLINDER}" --level 1)
run(2 refine "${CYLINDER}" --level 1 -o "${WORK}/no_such_dir/x.obj")
expect_contains("${ERR}" "cannot write")
run(2 frobnicate "${CYLINDER}")
run(2)

message(STATUS "cli tests passed")

# The evaluators write the same mesh (Vulkan falls back to the CPU, saying so, without a device).
foreach(evaluator cpu tbb vulkan)
  if(evaluator STREQUAL "vulkan")
    set(RUN_PREFIX ${VULKAN_PREFIX})
  endif()
  run(0 refine "${CYLINDER}" --level 2 --evaluator ${evaluator} -o "${WORK}/cyl_${evaluator}.obj")
  unset(RUN_PREFIX)
endforeach()
foreach(evaluator tbb vulkan)
  file(STRINGS "${WORK}/cyl_cpu.obj" cpuLines REGEX "^v ")
  file(STRINGS "${WORK}/cyl_${evaluator}.obj" otherLines REGEX "^v ")
  list(LENGTH cpuLines cpuCount)
  list(LENGTH otherLines otherCount)
  if(NOT cpuCount EQUAL otherCount OR cpuCount EQUAL 0)
    message(FATAL_ERROR "--evaluator ${evaluator}: ${otherCount} vertices, cpu ${cpuCount}")
  endif()
endforeach()
run(2 refine "${CYLINDER}" --level 1 --evaluator gpu -o "${WORK}/x.obj")
