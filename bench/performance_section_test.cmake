# ctest bench_performance_section: bench/performance_section.py on the --quick run's JSON, over
# copies of README.md (the headline table) and docs/performance.md (every figure). Each must name
# the run that made it, keep one pair of its marker lines, hold the expected rows, and come out
# the same when written twice (rerunning replaces a section, never appends).
#   cmake -DPYTHON=... -DSCRIPT=... -DJSON=... -DREADME=... -DDOC=... -DOUT_README=... -DOUT_DOC=...
#         -P performance_section_test.cmake
configure_file(${README} ${OUT_README} COPYONLY)
configure_file(${DOC} ${OUT_DOC} COPYONLY)
foreach(pass 1 2)
  execute_process(COMMAND ${PYTHON} ${SCRIPT} ${JSON} --readme ${OUT_README} --doc ${OUT_DOC} --note "ctest"
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "performance_section.py failed (pass ${pass}, exit ${rc})")
  endif()
  file(READ ${OUT_README} readme${pass})
  file(READ ${OUT_DOC} doc${pass})
endforeach()
if(NOT readme1 STREQUAL readme2)
  message(FATAL_ERROR "a second run of performance_section.py changed ${OUT_README}")
endif()
if(NOT doc1 STREQUAL doc2)
  message(FATAL_ERROR "a second run of performance_section.py changed ${OUT_DOC}")
endif()

# expect(TEXT NAME STRING...): every STRING occurs in TEXT (the file NAME).
function(expect text name)
  foreach(expected ${ARGN})
    string(FIND "${text}" "${expected}" at)
    if(at LESS 0)
      message(FATAL_ERROR "${name} lacks '${expected}'")
    endif()
  endforeach()
endfunction()
expect("${doc1}" "${OUT_DOC}"
       "<!-- performance-figures:begin" "<!-- performance-figures:end -->" "with `quadtri-bench --quick --json"
       "| torus100_quad | stam-loop/catmark | 2 |" "**The whole frame**"
       "| torus100_quad | catmull-clark/catmark | 2 | 10000 | 160000 | TbbEvaluator"
       "| mixed_limb | schaefer-warren | 2 | 9984 |"
       "| mixed_limb | catmull-clark/catmark | 2 | opensubdiv `bfr_tessellation` |"
       "| mixed_limb | schaefer-warren | 2 | edge | 129026 |")
expect("${readme1}" "${OUT_README}"
       "<!-- performance-headline:begin" "<!-- performance-headline:end -->" "with `quadtri-bench --quick --json"
       "| measured | quadtri | against" "| Whole frame: `mixed_limb` (9984 faces, schaefer-warren)"
       "| the same frame on one thread |" "| Whole frame on the pure cages (" "| Stencil evaluation, one thread ("
       "| Stencil evaluation, 2 threads" "| Factorized table build, topology included, one thread"
       "| Per-level table bytes")

# count(TEXT NAME MARKER): MARKER occurs exactly once in TEXT.
function(count_once text name marker)
  string(REGEX MATCHALL "${marker}" found "${text}")
  list(LENGTH found n)
  if(NOT n EQUAL 1)
    message(FATAL_ERROR "${n} '${marker}' lines in ${name} after two runs, expected 1")
  endif()
endfunction()
count_once("${doc1}" "${OUT_DOC}" "performance-figures:begin")
count_once("${doc1}" "${OUT_DOC}" "performance-figures:end")
count_once("${readme1}" "${OUT_README}" "performance-headline:begin")
count_once("${readme1}" "${OUT_README}" "performance-headline:end")

# The headline has 5 to 8 rows: the table's lines between the markers, less its header.
string(FIND "${readme1}" "performance-headline:begin" begin)
string(FIND "${readme1}" "performance-headline:end" end)
math(EXPR length "${end} - ${begin}")
string(SUBSTRING "${readme1}" ${begin} ${length} table)
string(REGEX MATCHALL "\n\\| [^\n]*\\|" rows "${table}")
set(headline 0)
foreach(row ${rows})
  if(NOT row MATCHES "\\| measured \\| quadtri \\|")
    math(EXPR headline "${headline} + 1")
  endif()
endforeach()
if(headline LESS 5 OR headline GREATER 8)
  message(FATAL_ERROR "the headline table in ${OUT_README} has ${headline} rows, expected 5 to 8")
endif()
