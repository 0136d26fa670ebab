# cmake --install: the public header, the library (SPIR-V embedded in it) and the CMake package
# lightscatterConfig.cmake with its version file, exporting one target, lightscatter::plugin.
#
#   <prefix>/include/lightscatter/lightscatter.h and the headers it includes (vocabulary.h,
#                                     settings.h, limits.h, methods.inc, methods/<method>.h)
#   <prefix>/lib/liblightscatter.a (LS_BUILD_SHARED: liblightscatter.so)
#   <prefix>/lib/cmake/lightscatter/lightscatterConfig.cmake, ...ConfigVersion.cmake, ...Targets*.cmake
#   <prefix>/lib/pkgconfig/lightscatter.pc
# A Debug build installs liblightscatterd.a (.so) beside a Release build's liblightscatter.a, each
# with its own lightscatterTargets-<config>.cmake: the package picks the one that matches the
# engine's configuration. `cpack -G DEB` in the build folder makes a development package of all this.
include(CMakePackageConfigHelpers)

if(LS_BUILD_SHARED)
  set(ls_installed lightscatter_plugin)  # the passes and the runtime are inside it
  set_target_properties(lightscatter_plugin PROPERTIES DEBUG_POSTFIX d)
  set(LS_PC_LIBS "")
else()
  # One archive with the plugin, the passes and the runtime, so that an engine links one library
  # with nothing to order; position-independent like the objects it is made of.
  add_library(lightscatter_package STATIC $<TARGET_OBJECTS:lightscatter_plugin>
                                          $<TARGET_OBJECTS:ls_passes> $<TARGET_OBJECTS:ls_beam_tree>
                                          $<TARGET_OBJECTS:rendergraph>)
  set_target_properties(lightscatter_package PROPERTIES OUTPUT_NAME lightscatter EXPORT_NAME plugin
                        LINKER_LANGUAGE CXX ARCHIVE_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/package
                        DEBUG_POSTFIX d)
  target_include_directories(lightscatter_package
                             INTERFACE $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(lightscatter_package INTERFACE cxx_std_17)
  target_link_libraries(lightscatter_package INTERFACE Vulkan::Headers ${CMAKE_DL_LIBS})
  set(ls_installed lightscatter_package)
  # A static archive's own needs: the loader's dlopen (the plugin finds libvulkan at run time).
  set(LS_PC_LIBS " -l${CMAKE_DL_LIBS}")
endif()
install(TARGETS ${ls_installed} EXPORT lightscatterTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/plugin_api/include/lightscatter
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${PROJECT_SOURCE_DIR}/vocabulary/lightscatter/vocabulary.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/lightscatter)
# Each method's settings header (lightscatter/methods/<method>.h).
get_property(ls_method_include_dirs GLOBAL PROPERTY LS_METHOD_INCLUDE_DIRS)
foreach(dir ${ls_method_include_dirs})
  install(DIRECTORY ${dir}/lightscatter DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()

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

# pkg-config, for builds without CMake (the Release library's name: a Debug install is CMake's).
# The prefix is this file's folder, up as many levels as the library folder is deep.
file(RELATIVE_PATH LS_PC_UP /root/${CMAKE_INSTALL_LIBDIR}/pkgconfig /root)
configure_file(${CMAKE_CURRENT_LIST_DIR}/lightscatter.pc.in ${PROJECT_BINARY_DIR}/lightscatter.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/lightscatter.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# cpack -G DEB: liblightscatter-dev, what cmake --install installs, under /usr.
set(CPACK_PACKAGE_NAME liblightscatter-dev)
set(CPACK_PACKAGE_VENDOR "lightscatter")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "volumetric light scattering for Vulkan engines (development files)")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "lightscatter developers")
set(CPACK_DEBIAN_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libvulkan-dev (>= 1.3)")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_GENERATOR DEB)
include(CPack)
