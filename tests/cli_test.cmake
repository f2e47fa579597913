# Runs the quadtri CLI and checks exit codes, messages and outputs.
#   cmake -DQUADTRI=<exe> -DVERSION=<project version> -DMESHES=<tests/meshes> -DWORK=<scratch dir> -P cli_test.cmake
foreach(var QUADTRI VERSION MESHES WORK)
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

# --version alone (no subcommand) prints project(VERSION) from CMakeLists.txt.
run(0 --version)
if(NOT OUT STREQUAL "quadtri ${VERSION}\n")
  message(FATAL_ERROR "${CMD}: expected 'quadtri ${VERSION}', got:\n${OUT}")
endif()

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
# catmull-clark splits the caps' triangles into quads too (144 corners: 144 quads), with or
# without the smooth-triangle rule; loop refuses the body's quads, naming the first in the file's
# numbering; the smooth-triangle rule is catmull-clark's alone.
run(0 refine "${CYLINDER}" --level 1 --scheme catmull-clark --smooth-triangles -o "${WORK}/cylinder_cc.obj")
count_lines("${WORK}/cylinder_cc.obj" "f " faces)
expect_equal("'f' lines of catmull-clark level 1" "${faces}" 144)
count_lines("${WORK}/cylinder_cc.obj" "f [0-9]+ [0-9]+ [0-9]+ [0-9]+$" quads)
expect_equal("quads of catmull-clark level 1" "${quads}" 144)
run(2 refine "${CYLINDER}" --level 1 --scheme loop -o "${WORK}/x.obj")
expect_contains("${ERR}" "cylinder_capped.obj:36: face 1: has 4 corners; the loop scheme takes triangles only")
run(2 info "${CYLINDER}" --smooth-triangles)
expect_contains("${ERR}" "catmull-clark")

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
# corners: left out), with a warning in the file's numbering.
run(0 refine "${WORK}/repeated.obj" --level 1 -o "${WORK}/x.obj")
expect_contains("${ERR}" "warning: ${WORK}/repeated.obj:6: face 2: vertex 3 appears again further on")

# A corner repeating the previous one is a collapsed edge: the quad is read as a triangle.
file(WRITE "${WORK}/collapsed.obj" "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 3 4\n")
run(0 info "${WORK}/collapsed.obj")
expect_contains("${OUT}" "3-gon 2")

# A crease tag on two vertices that share no edge is warned about (naming the tag's line) and
# ignored, as OpenSubdiv does.
file(WRITE "${WORK}/crease.obj" "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\nt crease 2/1/0 1 3 2.0\n")
run(0 info "${WORK}/crease.obj")
expect_contains("${ERR}" "warning: ${WORK}/crease.obj:7: t crease: vertices 1, 3 are not an edge of the mesh; crease ignored")

run(2 refine "${CYLINDER}" --level 1 --scheme catmark -o "${WORK}/x.obj")
expect_contains("${ERR}" "catmark")
run(2 refine "${CYLINDER}" --level 1 --boundary sometimes -o "${WORK}/x.obj")
run(2 refine "${CYLINDER}" --level -1 -o "${WORK}/x.obj")
run(2 refine "${CYLINDER}" --level 1)
run(2 refine "${CYLINDER}" --level 1 -o "${WORK}/no_such_dir/x.obj")
expect_contains("${ERR}" "no_such_dir/x.obj: cannot write file (No such file or directory)")
run(2 demo "${CYLINDER}" --levels 1 --out-dir=)
expect_contains("${ERR}" "--out-dir: ")
run(2 demo "${CYLINDER}" --levels 1 --out-dir "${WORK}/bad.obj")
expect_contains("${ERR}" "bad.obj: cannot create the output folder")
run(2 info "${WORK}")
expect_contains("${ERR}" "is a folder, not an OBJ file")
run(2 frobnicate "${CYLINDER}")
run(2)

# expect_one_line(): the run printed exactly one line on stderr (one clear error, not a page).
function(expect_one_line)
  string(REGEX MATCHALL "\n" newlines "${ERR}")
  list(LENGTH newlines n)
  if(NOT n EQUAL 1)
    message(FATAL_ERROR "${CMD}: ${n} lines on stderr, expected one:\n${ERR}")
  endif()
endfunction()

# --- files that are not meshes: one message naming what the file is ---------------------------
file(WRITE "${WORK}/empty.obj" "")
run(2 refine "${WORK}/empty.obj" --level 1 -o "${WORK}/x.obj")
expect_contains("${ERR}" "empty.obj: no faces to refine")
expect_one_line()
file(WRITE "${WORK}/points.obj" "v 0 0 0\nv 1 0 0\nv 0 1 0\n")
run(2 info "${WORK}/points.obj")
expect_contains("${ERR}" "points.obj: no faces to refine (3 vertices and no f line)")
string(ASCII 1 2 3 255 254 127 binary)
file(WRITE "${WORK}/binary.obj" "${binary}\n")
run(2 info "${WORK}/binary.obj")
expect_contains("${ERR}" "binary.obj:1: not an OBJ text file (byte 0x01 in column 1)")
expect_one_line()
file(WRITE "${WORK}/cube.ply" "ply\nformat ascii 1.0\nelement vertex 8\n")
run(2 refine "${WORK}/cube.ply" --level 1 -o "${WORK}/x.obj")
expect_contains("${ERR}" "cube.ply:1: a PLY file, not OBJ")
file(WRITE "${WORK}/scene.gltf" "{\n  \"asset\": { \"version\": \"2.0\" }\n}\n")
run(2 info "${WORK}/scene.gltf")
expect_contains("${ERR}" "scene.gltf:1: a glTF (JSON) file, not OBJ")
file(WRITE "${WORK}/scene.glb" "glTF")
run(2 info "${WORK}/scene.glb")
expect_contains("${ERR}" "scene.glb:1: a binary glTF (.glb) file, not OBJ")
file(WRITE "${WORK}/letter.txt" "Dear reader,\nthis is not a mesh.\n")
run(2 info "${WORK}/letter.txt")
expect_contains("${ERR}" "letter.txt:1: not an OBJ file")
expect_one_line()
string(REPEAT " 1" 200000 many)
file(WRITE "${WORK}/long_v.obj" "v${many}\nf 1 1 1\n")
run(2 info "${WORK}/long_v.obj")
expect_contains("${ERR}" "long_v.obj:1: v takes 3 or 4 coordinates (6 with colour), got 200000")
expect_one_line()
# Unknown statements: one warning per keyword, with its count and first line.
string(REPEAT "l 1 2\n" 500 lines)
file(WRITE "${WORK}/lines.obj" "v 0 0 0\nv 1 0 0\nv 0 1 0\n${lines}f 1 2 3\n")
run(0 info "${WORK}/lines.obj" --level 1)
expect_contains("${ERR}" "warning: ${WORK}/lines.obj:4: unknown statement 'l' ignored, 500 lines in all")
expect_one_line()

# A UTF-8 byte-order mark is skipped: the same mesh, refined to the same bytes.
file(READ "${CYLINDER}" cylinder_text)
string(ASCII 239 187 191 bom)
file(WRITE "${WORK}/bom.obj" "${bom}${cylinder_text}")
run(0 refine "${WORK}/bom.obj" --level 2 -o "${WORK}/bom_l2.obj")
file(SHA256 "${WORK}/bom_l2.obj" with_bom)
file(SHA256 "${WORK}/cylinder_l2.obj" without_bom)
expect_equal("level 2 of the file with a byte-order mark" "${with_bom}" "${without_bom}")

# Face diagnostics use the f statement's 1-based count and OBJ's 1-based vertices.
file(WRITE "${WORK}/collapsed_all.obj" "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n# a degenerate face\nf 2 2 2\n")
run(0 refine "${WORK}/collapsed_all.obj" --level 1 -o "${WORK}/x.obj")
expect_contains("${ERR}" "collapsed_all.obj:6: face 2: has fewer than 3 distinct corners: no area, left out")
file(WRITE "${WORK}/badtag.obj" "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nt corner 1/1/0 0 1\nt corner 1/1/0 3 1\n")
run(2 info "${WORK}/badtag.obj")
expect_contains("${ERR}" "badtag.obj:6: t corner: vertex 3 is out of range [0, 3)")
file(WRITE "${WORK}/badhole.obj" "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nt hole 1/0/0 1\n")
run(2 info "${WORK}/badhole.obj")
expect_contains("${ERR}" "badhole.obj:5: t hole: face index 1 is out of range [0, 1)")
# Tag counts near INT_MAX are added without overflow.
file(WRITE "${WORK}/bigcount.obj" "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nt crease 2147483647/1/0 0 1 1\n")
run(2 info "${WORK}/bigcount.obj")
expect_contains("${ERR}" "bigcount.obj:5: tag 'crease' announces 2147483648 arguments, has 3")

# --- output: only OBJ, never half written, an old file kept on failure -------------------------
run(2 refine "${CYLINDER}" --level 1 -o "${WORK}/out.gltf")
expect_contains("${ERR}" "out.gltf: only OBJ output (.obj) is written")
run(0 refine "${CYLINDER}" --level 1 -o "${WORK}/upper.OBJ")
file(WRITE "${WORK}/keep.obj" "old\n")
file(MAKE_DIRECTORY "${WORK}/folder.obj")
run(2 refine "${CYLINDER}" --level 1 -o "${WORK}/folder.obj")
expect_contains("${ERR}" "folder.obj: cannot write file (it is a directory)")
run(2 refine "${CYLINDER}" --level 1 -o "${WORK}/keep.obj/x.obj")
expect_contains("${ERR}" "cannot write file (Not a directory)")
file(READ "${WORK}/keep.obj" kept)
expect_equal("keep.obj after a failed write" "${kept}" "old\n")
file(GLOB temporaries "${WORK}/.*" "${WORK}/no_such_dir/*")
expect_equal("temporary files left" "${temporaries}" "")
if(EXISTS /dev/full)
  run(2 refine "${CYLINDER}" --level 1 -o /dev/full)
  expect_contains("${ERR}" "/dev/full: cannot write file (No space left on device)")
endif()
# Refining a file onto itself replaces it only once the new mesh is complete.
file(COPY_FILE "${CYLINDER}" "${WORK}/self.obj")
run(0 refine "${WORK}/self.obj" --level 1 -o "${WORK}/self.obj")
count_lines("${WORK}/self.obj" "v " vertices)
expect_equal("'v' lines of self.obj refined onto itself" "${vertices}" 130)

# --- the memory budget -------------------------------------------------------------------------
run(0 refine "${CYLINDER}" --level 1 --memory-budget 512MiB -o "${WORK}/x.obj")
foreach(bad "8 parsecs" -1 99999999999999999999 1.5GiB)
  run(2 info "${CYLINDER}" --memory-budget "${bad}")
  expect_contains("${ERR}" "'${bad}' is not a size: expected a whole number of bytes")
  expect_contains("${ERR}" "KiB, MiB, GiB, TiB (powers of 1024)")
endforeach()
# Level 2 of cylinder_capped needs at least its 514 output vertices of 12 bytes: 1KB is too little.
foreach(cmd refine info demo)
  set(extra)
  if(cmd STREQUAL "refine")
    set(extra --level 2 -o "${WORK}/budget.obj")
  elseif(cmd STREQUAL "info")
    set(extra --level 2)
  else()
    set(extra --levels 2 --out-dir "${WORK}/budget_demo")
    set(RUN_PREFIX ${VULKAN_PREFIX})
  endif()
  run(2 ${cmd} "${CYLINDER}" --memory-budget 1KB ${extra})
  unset(RUN_PREFIX)
  if(NOT ERR MATCHES "cylinder_capped.obj: level [0-2] needs at least [^\n]* over the memory budget of 1000 bytes; raise --memory-budget")
    message(FATAL_ERROR "${CMD}: no budget refusal naming the level, estimate and flag in:\n${ERR}")
  endif()
endforeach()
if(EXISTS "${WORK}/budget.obj")
  message(FATAL_ERROR "a refused refinement wrote ${WORK}/budget.obj")
endif()

# --- finite input, non-finite output: refused, naming the output vertex, nothing written -------
# Vertex 1 at +3.4e38 and the others of an icosahedron at -3.4e38 (x only): the butterfly's
# weights of one sign sum past 1 and overflow.
file(WRITE "${WORK}/overflow.obj" "v 3.4e38 0 0\n")
foreach(i RANGE 2 12)
  file(APPEND "${WORK}/overflow.obj" "v -3.4e38 0 0\n")
endforeach()
file(STRINGS "${MESHES}/osd/loop_icosahedron.obj" icosahedron_faces REGEX "^f ")
foreach(face ${icosahedron_faces})
  file(APPEND "${WORK}/overflow.obj" "${face}\n")
endforeach()
foreach(cmd refine demo)
  if(cmd STREQUAL "refine")
    run(2 refine "${WORK}/overflow.obj" --level 1 --scheme catmark-butterfly -o "${WORK}/overflow_l1.obj")
  else()
    set(RUN_PREFIX ${VULKAN_PREFIX})
    run(2 demo "${WORK}/overflow.obj" --levels 1 --scheme catmark-butterfly --out-dir "${WORK}/overflow_demo")
    unset(RUN_PREFIX)
  endif()
  if(NOT ERR MATCHES "overflow.obj: level 1: output vertex [0-9]+ has coordinate -?inf; the input's largest coordinate magnitude, 3.4e\\+38, leaves no headroom")
    message(FATAL_ERROR "${CMD}: no overflow error naming the vertex in:\n${ERR}")
  endif()
endforeach()
if(EXISTS "${WORK}/overflow_l1.obj" OR EXISTS "${WORK}/overflow_demo/overflow_level1.obj")
  message(FATAL_ERROR "an overflowing refinement was written")
endif()
# The same mesh under bilinear weights (all positive, summing to 1) stays finite.
run(0 refine "${WORK}/overflow.obj" --level 1 --scheme bilinear -o "${WORK}/overflow_bilinear.obj")

# --- Vulkan device selection: a bad QUADTRI_VK_DEVICE says what would be accepted --------------
set(RUN_PREFIX ${VULKAN_PREFIX} QUADTRI_VK_DEVICE=99999999999999999999)
run(0 refine "${CYLINDER}" --level 1 --evaluator vulkan -o "${WORK}/x.obj")
unset(RUN_PREFIX)
if(NOT WITH_VULKAN)  # a build without Vulkan says so and uses the CPU
  expect_contains("${ERR}" "built without Vulkan (QUADTRI_WITH_VULKAN=OFF); using the CPU evaluator")
elseif(NOT ERR MATCHES "Vulkan unavailable")
  message(FATAL_ERROR "${CMD}: no word about Vulkan:\n${ERR}")
elseif(NOT ERR MATCHES "no Vulkan|no driver|vkCreateInstance")  # with a driver, the device list
  expect_contains("${ERR}" "QUADTRI_VK_DEVICE '99999999999999999999': no device with that index; expected an index 0")
endif()

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
