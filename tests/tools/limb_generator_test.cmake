# data/mixed_limb.obj is tools/make_limb.py's output, byte for byte.
#   cmake -DPYTHON=<python3> -DSOURCE=<repository root> -DWORK=<scratch dir> -P limb_generator_test.cmake
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND "${PYTHON}" "${SOURCE}/tools/make_limb.py" OUTPUT_FILE "${WORK}/mixed_limb.obj"
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc STREQUAL "0")
  message(FATAL_ERROR "tools/make_limb.py failed (${rc}):\n${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${WORK}/mixed_limb.obj" "${SOURCE}/data/mixed_limb.obj"
                RESULT_VARIABLE differs)
if(differs)
  message(FATAL_ERROR "data/mixed_limb.obj is not what tools/make_limb.py writes: regenerate it with\n"
                      "  python3 tools/make_limb.py > data/mixed_limb.obj")
endif()
