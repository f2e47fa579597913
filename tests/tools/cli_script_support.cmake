# What the CLI test scripts (cli_test.cmake, render_cli_test.cmake) share: running quadtri with a
# command prefix and checking its exit status and message, and text checks on what it printed.

# run_quadtri(<prefix list> <expected exit code> <args>...): runs quadtri under the prefix (an
# environment wrapper, or nothing), leaves OUT, ERR and the command line in CMD, and fails unless
# the status is the expected one and a failure's stderr starts with "quadtri: ".
macro(run_quadtri prefix expected)
  set(CMD "quadtri ${ARGN}")
  execute_process(COMMAND ${${prefix}} "${QUADTRI}" ${ARGN} RESULT_VARIABLE RC OUTPUT_VARIABLE OUT
                  ERROR_VARIABLE ERR TIMEOUT 120)
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
