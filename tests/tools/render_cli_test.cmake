# Runs `quadtri render` and checks its PNGs (signature, IHDR size), exit codes and messages.
#   cmake -DQUADTRI=<exe> -DDATA=<data/> -DWORK=<scratch dir> -P render_cli_test.cmake
foreach(var QUADTRI DATA WORK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "render_cli_test.cmake needs -D${var}=...")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

# The validation layer on, so that its messages show up on stderr; leak checking off in the
# sanitizer build (lavapipe's globals once the loader unloads it, as in cli_test.cmake).
set(PREFIX ${CMAKE_COMMAND} -E env QUADTRI_VK_VALIDATION=1 ASAN_OPTIONS=detect_leaks=0:abort_on_error=1)

include(${CMAKE_CURRENT_LIST_DIR}/cli_script_support.cmake)
macro(run expected)
  set(RUN_PREFIX ${PREFIX} ${EXTRA_ENV})
  run_quadtri(RUN_PREFIX ${expected} ${ARGN})
  if("${expected}" STREQUAL "0" AND ERR MATCHES "Vulkan validation (warning|error)|validation layer reported")
    message(FATAL_ERROR "${CMD}: the validation layer spoke:\n${ERR}")
  endif()
endmacro()

# A PNG: the 8-byte signature, then the IHDR chunk with the width and height (big-endian).
function(expect_png file width height)
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "${CMD}: did not write ${file}")
  endif()
  file(READ "${file}" head LIMIT 24 HEX)
  string(SUBSTRING "${head}" 0 16 signature)
  string(SUBSTRING "${head}" 24 8 chunk)
  string(SUBSTRING "${head}" 32 8 w)
  string(SUBSTRING "${head}" 40 8 h)
  math(EXPR w "0x${w}")
  math(EXPR h "0x${h}")
  if(NOT signature STREQUAL "89504e470d0a1a0a" OR NOT chunk STREQUAL "49484452")
    message(FATAL_ERROR "${CMD}: ${file} is not a PNG (starts ${head})")
  endif()
  if(NOT w EQUAL ${width} OR NOT h EQUAL ${height})
    message(FATAL_ERROR "${CMD}: ${file} is ${w}x${h}, expected ${width}x${height}")
  endif()
endfunction()

set(TORUS "${DATA}/mixed_torus.obj")
set(CYLINDER "${DATA}/cylinder_capped.obj")

# Without a device (none matches QUADTRI_VK_DEVICE), one clear line and exit 2 before
# anything is written.
set(EXTRA_ENV QUADTRI_VK_DEVICE=no-such-device)
run(2 render "${TORUS}" -o "${WORK}/none.png")
unset(EXTRA_ENV)
expect_contains("${ERR}" "quadtri: render needs a Vulkan device: ")
if(EXISTS "${WORK}/none.png")
  message(FATAL_ERROR "${CMD}: wrote a file without a device")
endif()
if(NOT ERR MATCHES "no Vulkan device with a queue family for graphics and compute matches QUADTRI_VK_DEVICE|no Vulkan driver|no Vulkan device found")
  message(FATAL_ERROR "${CMD}: no reason given:\n${ERR}")
endif()

# Each shading, each evaluator: a PNG of the requested size.
run(0 render "${TORUS}" --level 1 --size 64x48 -o "${WORK}/torus.png")
expect_png("${WORK}/torus.png" 64 48)
foreach(shading smooth flat reflection-lines mean-curvature face-type)
  run(0 render "${TORUS}" --level 2 --size 48x40 --shading ${shading} --cage --points -o "${WORK}/${shading}.png")
  expect_png("${WORK}/${shading}.png" 48 40)
endforeach()
foreach(evaluator cpu tbb vulkan)
  run(0 render "${CYLINDER}" --level 2 --limit --size 40x40 --evaluator ${evaluator} --shading mean-curvature
      -o "${WORK}/cylinder_${evaluator}.png")
  expect_png("${WORK}/cylinder_${evaluator}.png" 40 40)
endforeach()
# --compare: one panel per scheme, side by side; the flags of the view.
run(0 render "${TORUS}" --level 1 --size 50x40 --compare catmull-clark,stam-loop,schaefer-warren
    --yaw -40 --pitch 60 --light-dir 0,1,0 --light-color 1,0.9,0.8 --stripes 8 --shading reflection-lines
    -o "${WORK}/compare.png")
expect_png("${WORK}/compare.png" 150 40)
# Supersampled: the size asked for, not K times it.
run(0 render "${TORUS}" --level 1 --size 40x30 --supersample 3 --label "level 1, naïve\ttab" -o "${WORK}/supersampled.png")
expect_png("${WORK}/supersampled.png" 40 30)
# A texture (a PNG written above), the crease override, the surface hidden.
run(0 render "${CYLINDER}" --level 1 --size 32x32 --shading textured --texture "${WORK}/torus.png"
    --crease-sharpness 2.5 --no-surface --cage -o "${WORK}/textured.png")
expect_png("${WORK}/textured.png" 32 32)
expect_contains("${ERR}" "has no UVs")

# Bad input: the flag's own message, exit 2, nothing written.
foreach(bad "--size;0x0" "--size;64" "--size;64x48x3" "--shading;glossy" "--compare;catmull-clark,nope"
            "--pitch;95" "--light-color;2,0,0" "--light-dir;1,2" "--evaluator;gpu" "--level;11"
            "--crease-sharpness;-1" "--stripes;0" "--supersample;5"
            "--light-dir;0,0,0")
  run(2 render "${TORUS}" ${bad} -o "${WORK}/bad.png")
endforeach()
run(2 render "${TORUS}" --compare nope -o "${WORK}/bad.png")
expect_contains("${ERR}" "unknown scheme 'nope'")
run(2 render "${TORUS}" --texture "${WORK}/missing.png" -o "${WORK}/bad.png")
expect_contains("${ERR}" "missing.png: cannot read the image")
file(WRITE "${WORK}/broken.obj" "v 0 0 0\nv 1 0 0\nf 1 2 7\n")
run(2 render "${WORK}/broken.obj" -o "${WORK}/bad.png")
expect_contains("${ERR}" "broken.obj:3")
run(2 render "${TORUS}" --size 8192x8192 --supersample 4 --level 0 -o "${WORK}/bad.png")
expect_contains("${ERR}" "pixels: the Vulkan device draws 1 to")
run(2 render "${TORUS}" --size 32x32 -o "${WORK}/no/such/folder/x.png")
expect_contains("${ERR}" "cannot write file")
if(EXISTS "${WORK}/bad.png")
  message(FATAL_ERROR "a refused run wrote ${WORK}/bad.png")
endif()
message(STATUS "render CLI: all checks passed")
