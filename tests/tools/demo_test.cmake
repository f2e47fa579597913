# `quadtri demo` on the bundled cage, a few frames: the lines a newcomer reads, and the
# evaluators' agreement it prints.
#   cmake -DQUADTRI=<exe> -DCAGE=<data/mixed_limb.obj> -DWITH_VULKAN=ON|OFF -P demo_test.cmake
foreach(var QUADTRI CAGE WITH_VULKAN)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "demo_test.cmake needs -D${var}=...")
  endif()
endforeach()
# LeakSanitizer and lavapipe: see cli_test.cmake's VULKAN_PREFIX.
execute_process(COMMAND ${CMAKE_COMMAND} -E env ASAN_OPTIONS=detect_leaks=0:abort_on_error=1
                        "${QUADTRI}" demo "${CAGE}" --level 1 --frames 3
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
set(cmd "quadtri demo ${CAGE} --level 1 --frames 3")
if(NOT rc STREQUAL "0")
  message(FATAL_ERROR "${cmd}: exit status '${rc}'\nstdout:\n${out}\nstderr:\n${err}")
endif()

function(expect_line regex what)
  if(NOT out MATCHES "${regex}")
    message(FATAL_ERROR "${cmd}: no ${what} in:\n${out}\nstderr:\n${err}")
  endif()
endfunction()

# 8066 vertices and 9984 faces (6144 quads, 3840 triangles, tools/make_limb.py); level 1 adds a
# point per edge (18048) and per quad: 32258 vertices, 4 faces per face.
expect_line("mixed_limb.obj: 8066 vertices, 9984 faces \\(6144 quads, 3840 triangles\\); scheme schaefer-warren\n"
            "the cage line")
expect_line("\nlevel 1: 32258 vertices, 39936 faces; limit positions and normals through the factorized limit tables"
            "the level line")
expect_line("\nskin: two bones along x joined at \\([-0-9.e]+, [-0-9.e]+, [-0-9.e]+\\), blended over 20% of the length; bend about y"
            "the skin line")
expect_line("\ntbb against cpu, same frame: positions within 0, normals within 0\n" "bitwise cpu = tbb")
set(number "[0-9]+\\.[0-9]+")
set(row " 3 \\| ${number} \\| ${number} \\| \\(in evaluate\\) \\| ${number} \\| ${number} \\|\n")
expect_line("\n\\| evaluator \\| frames \\| deform ms \\| evaluate ms \\| normals ms \\| frame ms \\| fps \\|\n" "the table's head")
expect_line("\n\\| cpu \\|${row}\\| tbb \\|${row}" "the cpu and tbb rows")
if(WITH_VULKAN)
  # A device: its name, its agreement within 1e-5 (a single digit before e-06 or e-07 ...), its row.
  # No device: the reason on stderr, and no row.
  if(out MATCHES "\nvulkan: device ")
    expect_line("\nvulkan against cpu, same frame: positions within ([0-9.]+e-0[6-9]|0), normals within ([0-9.]+e-0[6-9]|0)\n"
                "Vulkan's agreement within 1e-5")
    expect_line("\\| vulkan \\|${row}" "the vulkan row")
  elseif(NOT err MATCHES "quadtri: Vulkan unavailable \\(.*\\); vulkan skipped")
    message(FATAL_ERROR "${cmd}: neither a Vulkan device nor the reason for its absence:\n${out}\nstderr:\n${err}")
  endif()
endif()
