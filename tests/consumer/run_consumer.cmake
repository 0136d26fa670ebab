# CTest driver for the consumer projects (cmake -P). Builds and runs an engine against lightscatter:
#   -DMODE=package       installs BUILD_DIR into WORK_DIR/prefix (cmake --install), checks what was
#                        installed, builds tests/consumer/package against it and runs it, and the
#                        volk-style engine, after checking with READELF that it needs no libvulkan
#   -DMODE=deb           makes the Debian package (cpack -G DEB in BUILD_DIR), unpacks it into a
#                        scratch root, checks its name and dependencies, and builds the same engine
#                        against the root's /usr
#   -DMODE=configs       installs BUILD_DIR (Release) and a Debug build of the library alone into one
#                        prefix, then builds the same engine in Debug and in Release against it: each
#                        must link its own configuration's library (liblightscatterd.a, liblightscatter.a)
#   -DMODE=subdirectory  builds tests/consumer/subdirectory (add_subdirectory of SOURCE_DIR, shared
#                        library), checks that the library exports only lightscatter::, runs it
# Other variables: SOURCE_DIR, BUILD_DIR, WORK_DIR, JOBS, NM, READELF.
foreach(var MODE SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_consumer.cmake needs -D${var}=...")
  endif()
endforeach()
if(NOT JOBS)
  set(JOBS 2)
endif()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " line "${ARGN}")
    message(FATAL_ERROR "${line}\nfailed (${rc}):\n${out}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(consumer_build ${WORK_DIR}/build)

if(MODE STREQUAL "package")
  set(prefix ${WORK_DIR}/prefix)
  run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
  # One header, the libraries with their SPIR-V inside, the package and its version file.
  file(GLOB_RECURSE installed RELATIVE ${prefix} ${prefix}/*)
  list(SORT installed)
  string(REPLACE ";" "\n  " listing "${installed}")
  message(STATUS "installed:\n  ${listing}")
  foreach(expected include/lightscatter/lightscatter.h include/lightscatter/vocabulary.h
                   include/lightscatter/settings.h include/lightscatter/methods.inc
                   include/lightscatter/methods/epipolar.h
                   pkgconfig/lightscatter.pc lightscatterConfig.cmake
                   lightscatterConfigVersion.cmake lightscatterTargets.cmake liblightscatter.a)
    if(NOT installed MATCHES "(^|;|/)${expected}(;|$)")
      message(FATAL_ERROR "cmake --install did not install ${expected}")
    endif()
  endforeach()
  foreach(file IN LISTS installed)
    # The public header and what it includes: the settings, the limits, the list of methods and
    # each method's settings; the shaders live inside the library.
    if(file MATCHES "\\.(spv|h|hpp|inc)$" AND NOT file MATCHES
       "^include/lightscatter/((lightscatter|vocabulary|settings|limits)\\.h|methods\\.inc|methods/[a-z_]+\\.h)$")
      message(FATAL_ERROR "cmake --install installed ${file}: only lightscatter.h and the headers it "
                          "includes are public, and the shaders live inside the library")
    endif()
    if(file MATCHES "\\.a$" AND NOT file MATCHES "/liblightscatter\\.a$")
      message(FATAL_ERROR "cmake --install installed ${file}: the package is one library")
    endif()
  endforeach()
  # One exported target, which needs nothing but Vulkan.
  file(GLOB targets_file ${prefix}/*/cmake/lightscatter/lightscatterTargets.cmake)
  file(READ ${targets_file} exported)
  string(REGEX MATCHALL "add_library\\([^ ]+" defined "${exported}")
  if(NOT defined STREQUAL "add_library(lightscatter::plugin")
    message(FATAL_ERROR "the package defines ${defined}; it should define lightscatter::plugin alone")
  endif()
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer/package -B ${consumer_build}
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix})
elseif(MODE STREQUAL "deb")
  get_filename_component(cmake_bin "${CMAKE_COMMAND}" DIRECTORY)
  run(${cmake_bin}/cpack -G DEB -B ${WORK_DIR}/cpack --config ${BUILD_DIR}/CPackConfig.cmake)
  file(GLOB debs ${WORK_DIR}/cpack/*.deb)
  list(LENGTH debs count)
  if(NOT count EQUAL 1)
    message(FATAL_ERROR "cpack -G DEB made ${count} packages: ${debs}")
  endif()
  run(dpkg-deb -f ${debs} Package Depends Version)
  if(NOT last_output MATCHES "Package: liblightscatter-dev" OR NOT last_output MATCHES "Depends: libvulkan-dev")
    message(FATAL_ERROR "the package's control fields:\n${last_output}")
  endif()
  message(STATUS "${debs}:\n${last_output}")
  run(dpkg-deb -x ${debs} ${WORK_DIR}/root)
  set(prefix ${WORK_DIR}/root/usr)
  file(GLOB_RECURSE packaged RELATIVE ${WORK_DIR}/root ${WORK_DIR}/root/*)
  foreach(expected usr/include/lightscatter/lightscatter.h lightscatter.pc lightscatterConfig.cmake)
    if(NOT packaged MATCHES "(^|;|/)${expected}(;|$)")
      message(FATAL_ERROR "the package holds no ${expected}: ${packaged}")
    endif()
  endforeach()
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer/package -B ${consumer_build}
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix})
elseif(MODE STREQUAL "configs")
  set(prefix ${WORK_DIR}/prefix)
  run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
  set(debug_build ${WORK_DIR}/debug)
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${debug_build} -DCMAKE_BUILD_TYPE=Debug -DLS_BUILD_TESTS=OFF
      -DLS_BUILD_HOST_EXAMPLE=OFF)
  run(${CMAKE_COMMAND} --build ${debug_build} -j ${JOBS} --target lightscatter_package)
  run(${CMAKE_COMMAND} --install ${debug_build} --prefix ${prefix})
  file(GLOB_RECURSE libraries RELATIVE ${prefix} ${prefix}/*.a)
  file(GLOB_RECURSE per_config RELATIVE ${prefix} ${prefix}/*/lightscatterTargets-*.cmake)
  list(LENGTH libraries library_count)
  list(LENGTH per_config config_count)
  if(NOT library_count EQUAL 2 OR NOT libraries MATCHES "liblightscatterd\\.a" OR NOT config_count EQUAL 2)
    message(FATAL_ERROR "Debug beside Release installed ${libraries} and ${per_config}: expected "
                        "liblightscatter.a, liblightscatterd.a and one targets file per configuration")
  endif()
  foreach(config Debug Release)
    set(build ${WORK_DIR}/build-${config})
    run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer/package -B ${build} -DCMAKE_BUILD_TYPE=${config}
        -DCMAKE_PREFIX_PATH=${prefix})
    run(${CMAKE_COMMAND} --build ${build} -j ${JOBS} -v --target headless_engine)
    if(config STREQUAL "Debug")
      set(wanted "liblightscatterd\\.a")
      set(other "liblightscatter\\.a")
    else()
      set(wanted "liblightscatter\\.a")
      set(other "liblightscatterd\\.a")
    endif()
    if(NOT last_output MATCHES "${wanted}" OR last_output MATCHES "${other}")
      message(FATAL_ERROR "the ${config} engine did not link its own configuration's library:\n${last_output}")
    endif()
    run(${build}/headless_engine)
    message(STATUS "${config} headless_engine (linked ${wanted}):\n${last_output}")
  endforeach()
  return()
elseif(MODE STREQUAL "subdirectory")
  # No build type given: the engine's empty CMAKE_BUILD_TYPE must survive add_subdirectory.
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer/subdirectory -B ${consumer_build}
      -DLIGHTSCATTER_SOURCE_DIR=${SOURCE_DIR})
else()
  message(FATAL_ERROR "MODE must be package, deb, configs or subdirectory, not '${MODE}'")
endif()

run(${CMAKE_COMMAND} --build ${consumer_build} -j ${JOBS})

if(MODE STREQUAL "subdirectory")
  file(GLOB_RECURSE shared_library ${consumer_build}/lightscatter/liblightscatter.so)
  if(NOT shared_library)
    message(FATAL_ERROR "LS_BUILD_SHARED built no liblightscatter.so")
  endif()
  run(${NM} -D --defined-only -C ${shared_library})
  string(REPLACE "\n" ";" symbols "${last_output}")
  set(api 0)
  set(foreign "")
  foreach(line IN LISTS symbols)
    # "<address> <type> <name>"; names may hold spaces.
    if(NOT line MATCHES "^[0-9a-fA-F]+ [A-Za-z] (.*)$")
      continue()
    endif()
    set(name "${CMAKE_MATCH_1}")
    string(REGEX REPLACE "^(typeinfo name for |typeinfo for |vtable for )" "" name "${name}")
    if(name MATCHES "^lightscatter::" AND NOT name MATCHES "^lightscatter::detail::")
      math(EXPR api "${api} + 1")
    elseif(NOT name MATCHES "^LIGHTSCATTER_")  # the version node, if any
      string(APPEND foreign "\n  ${line}")
    endif()
  endforeach()
  if(foreign)
    message(FATAL_ERROR "liblightscatter.so exports more than the lightscatter:: API:${foreign}")
  endif()
  if(api LESS 10)
    message(FATAL_ERROR "liblightscatter.so exports only ${api} lightscatter:: symbols")
  endif()
  message(STATUS "liblightscatter.so exports ${api} symbols, all lightscatter:: API")
endif()

run(${consumer_build}/headless_engine)
message(STATUS "headless_engine:\n${last_output}")

if(MODE STREQUAL "package")
  # The plugin in an engine that links no loader: the libraries the executable needs, as the
  # dynamic loader reads them, name none of Vulkan's.
  if(NOT READELF)
    set(READELF readelf)
  endif()
  run(${READELF} -d ${consumer_build}/volk_style_engine)
  string(REGEX MATCHALL "\\(NEEDED\\)[^\n]*" needed "${last_output}")
  if(NOT needed)
    message(FATAL_ERROR "readelf -d volk_style_engine listed no NEEDED entry:\n${last_output}")
  endif()
  if(needed MATCHES "libvulkan")
    message(FATAL_ERROR "volk_style_engine needs the Vulkan loader:\n${last_output}")
  endif()
  string(REPLACE ";" "\n  " needed "${needed}")
  message(STATUS "volk_style_engine needs:\n  ${needed}")
  run(${consumer_build}/volk_style_engine)
  message(STATUS "volk_style_engine:\n${last_output}")

  # An engine built without CMake: the compiler's flags from pkg-config alone.
  file(GLOB_RECURSE pc_file ${prefix}/lightscatter.pc)
  get_filename_component(pc_dir "${pc_file}" DIRECTORY)
  set(ENV{PKG_CONFIG_PATH} "${pc_dir}")
  run(pkg-config --cflags --libs lightscatter)
  string(STRIP "${last_output}" pc_flags)
  message(STATUS "pkg-config --cflags --libs lightscatter: ${pc_flags}")
  separate_arguments(pc_flags UNIX_COMMAND "${pc_flags}")
  run(c++ -o ${WORK_DIR}/pkgconfig_engine ${SOURCE_DIR}/tests/consumer/engine/headless_engine.cpp
      ${SOURCE_DIR}/tests/plugin/readme_example.cpp -I${SOURCE_DIR}/tests/plugin ${pc_flags} -lvulkan)
  run(${WORK_DIR}/pkgconfig_engine)
  message(STATUS "pkgconfig_engine:\n${last_output}")
endif()
