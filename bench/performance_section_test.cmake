# ctest bench_performance_section: bench/performance_section.py on the --quick run's JSON, over a
# copy of README.md. The section must name the run that made it, keep both marker lines, and
# come out the same when written twice (rerunning replaces it, never appends).
#   cmake -DPYTHON=... -DSCRIPT=... -DJSON=... -DREADME=... -DOUT=... -P performance_section_test.cmake
configure_file(${README} ${OUT} COPYONLY)
foreach(pass 1 2)
  execute_process(COMMAND ${PYTHON} ${SCRIPT} ${JSON} --readme ${OUT} --note "ctest" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "performance_section.py failed (pass ${pass}, exit ${rc})")
  endif()
  file(READ ${OUT} text${pass})
endforeach()
if(NOT text1 STREQUAL text2)
  message(FATAL_ERROR "a second run of performance_section.py changed ${OUT}")
endif()
foreach(expected "<!-- performance-figures:begin" "<!-- performance-figures:end -->" "with `quadtri-bench --quick --json"
                 "| torus100_quad | stam-loop/catmark | 2 |" "**The whole frame**"
                 "| torus100_quad | catmull-clark/catmark | 2 | 10000 | 160000 | TbbEvaluator"
                 "| mixed_limb | schaefer-warren | 2 | 9984 |")
  string(FIND "${text1}" "${expected}" at)
  if(at LESS 0)
    message(FATAL_ERROR "the written section lacks '${expected}'")
  endif()
endforeach()
string(REGEX MATCHALL "performance-figures:begin" begins "${text1}")
list(LENGTH begins count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "${count} begin markers after two runs, expected 1")
endif()
