# cmake --install: the public header, the libraries (SPIR-V embedded in them) and the CMake package
# lightscatterConfig.cmake with its version file, exporting lightscatter::plugin.
#
#   <prefix>/include/lightscatter/lightscatter.h
#   <prefix>/lib/liblightscatter.a, liblightscatter_passes.a, liblightscatter_rendergraph.a
#     (LS_BUILD_SHARED: liblightscatter.so alone)
#   <prefix>/lib/cmake/lightscatter/lightscatterConfig.cmake, ...ConfigVersion.cmake, ...Targets*.cmake
include(CMakePackageConfigHelpers)

set(ls_installed lightscatter_plugin)
if(NOT LS_BUILD_SHARED)
  # A static plugin needs the passes and the runtime after it; an engine never names them.
  set_target_properties(ls_passes PROPERTIES EXPORT_NAME passes)
  set_target_properties(rendergraph PROPERTIES EXPORT_NAME rendergraph)
  list(APPEND ls_installed ls_passes rendergraph)
endif()
install(TARGETS ${ls_installed} EXPORT lightscatterTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${PROJECT_SOURCE_DIR}/plugin_api/lightscatter.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/lightscatter)

set(ls_package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/lightscatter)
install(EXPORT lightscatterTargets NAMESPACE lightscatter:: DESTINATION ${ls_package_dir})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/lightscatterConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/lightscatterConfig.cmake
                              INSTALL_DESTINATION ${ls_package_dir})
# 0.x: a minor version may change the API, so only the same major.minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/lightscatterConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/lightscatterConfig.cmake
              ${PROJECT_BINARY_DIR}/lightscatterConfigVersion.cmake
        DESTINATION ${ls_package_dir})
