# cmake --install: the libraries, the public headers only (the QUADTRI_PUBLIC_HEADERS_* lists and
# the generated version.h and quadtri.h; the private headers of far/*/, osd/internal/, osd/vulkan/
# and kernels/ stay out), the CLI when built, a CMake package (find_package(quadtri CONFIG), targets quadtri::quadtri and
# quadtri::vulkan) and pkg-config files. Included at the end of the top-level CMakeLists.txt.
include(CMakePackageConfigHelpers)

set(QUADTRI_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/quadtri)
set(QUADTRI_PKGCONFIG_DIR ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

install(TARGETS quadtri EXPORT quadtriTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${QUADTRI_PUBLIC_HEADERS_FAR} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/quadtri/far)
install(FILES ${QUADTRI_PUBLIC_HEADERS_OSD} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/quadtri/osd)
install(FILES ${QUADTRI_INCLUDE_ROOT}/quadtri/version.h ${QUADTRI_INCLUDE_ROOT}/quadtri/export.h ${QUADTRI_INCLUDE_ROOT}/quadtri/quadtri.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/quadtri)
if(QUADTRI_WITH_TBB)
  set_target_properties(quadtri_tbb PROPERTIES EXPORT_NAME tbb)
  install(TARGETS quadtri_tbb EXPORT quadtriTargets)
endif()
install(EXPORT quadtriTargets NAMESPACE quadtri:: DESTINATION ${QUADTRI_CMAKE_DIR})
# The license (Apache-2.0) beside the documentation, as Debian places it.
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/quadtri)

# The Vulkan evaluator is a component of its own, in its own targets file, so that a consumer of
# the core never needs Vulkan (quadtriConfig.cmake looks for it only when asked or when present).
if(QUADTRI_WITH_VULKAN)
  set_target_properties(quadtri_vulkan PROPERTIES EXPORT_NAME vulkan)
  install(TARGETS quadtri_vulkan EXPORT quadtriVulkanTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(FILES ${QUADTRI_PUBLIC_HEADERS_VULKAN} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/quadtri/osd)
  install(EXPORT quadtriVulkanTargets NAMESPACE quadtri:: DESTINATION ${QUADTRI_CMAKE_DIR})
endif()

if(QUADTRI_BUILD_TOOLS)
  install(TARGETS quadtri_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/quadtriConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/quadtriConfig.cmake INSTALL_DESTINATION ${QUADTRI_CMAKE_DIR})
# 0.x: SameMajorVersion accepts any 0.y for a request of 0.x with y >= x.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/quadtriConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/quadtriConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/quadtriConfigVersion.cmake
  DESTINATION ${QUADTRI_CMAKE_DIR})

# pkg-config: the prefix is found from the .pc file's own place (${pcfiledir}), so that
# `cmake --install --prefix P` works whatever CMAKE_INSTALL_PREFIX was at configure time.
file(RELATIVE_PATH QUADTRI_PC_TO_PREFIX /prefix/${QUADTRI_PKGCONFIG_DIR} /prefix)
string(REGEX REPLACE "/$" "" QUADTRI_PC_TO_PREFIX "${QUADTRI_PC_TO_PREFIX}")
set(QUADTRI_PC_PREFIX "\${pcfiledir}/${QUADTRI_PC_TO_PREFIX}")
if(QUADTRI_WITH_TBB)
  set(QUADTRI_PC_REQUIRES tbb)
else()
  set(QUADTRI_PC_REQUIRES "")
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/quadtri.pc.in ${CMAKE_CURRENT_BINARY_DIR}/quadtri.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/quadtri.pc DESTINATION ${QUADTRI_PKGCONFIG_DIR})
if(QUADTRI_WITH_VULKAN)
  configure_file(${CMAKE_CURRENT_LIST_DIR}/quadtri-vulkan.pc.in ${CMAKE_CURRENT_BINARY_DIR}/quadtri-vulkan.pc @ONLY)
  install(FILES ${CMAKE_CURRENT_BINARY_DIR}/quadtri-vulkan.pc DESTINATION ${QUADTRI_PKGCONFIG_DIR})
endif()
