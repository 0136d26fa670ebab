# Compiles GLSL to SPIR-V at build time and embeds each module as a uint32_t array in a generated
# header, so binaries carry their shaders and never look for .spv files at run time.
#
#   ls_embed_shaders(TARGET <interface-lib> SOURCES a.comp b.frag ... [INCLUDE_DIRS dir ...])
#
# Each source <dir>/<name>.<stage> becomes <build>/shaders_gen/<name>_<stage>.h defining
# `inline constexpr uint32_t <name>_<stage>[]` inside namespace ls_spirv. A source written as
# `path@variant@DEF1=1,DEF2=1` is compiled with those macros as <name>_<variant>_<stage>: resource
# bindings that only some lights need are variants, not specialisation constants, so a pipeline
# never declares a descriptor it is not given. Includes are tracked with
# glslang's depfile so editing a shared .glsl file rebuilds its users.
#
# Paths are this project's own (PROJECT_BINARY_DIR, this file's folder), never the top-level
# project's, so the function works when lightscatter is added to an engine with add_subdirectory.

function(ls_embed_shaders)
  cmake_parse_arguments(ARG "" "TARGET" "SOURCES;INCLUDE_DIRS" ${ARGN})
  set(out_dir ${PROJECT_BINARY_DIR}/shaders_gen)
  file(MAKE_DIRECTORY ${out_dir})
  set(include_flags)
  foreach(dir ${ARG_INCLUDE_DIRS})
    list(APPEND include_flags -I${dir})
  endforeach()
  set(headers)
  foreach(item ${ARG_SOURCES})
    string(REPLACE "@" ";" parts "${item}")
    list(GET parts 0 src)
    list(LENGTH parts nparts)
    set(variant "")
    set(define_flags)
    if(nparts GREATER 1)
      list(GET parts 1 variant)
      set(variant "_${variant}")
    endif()
    if(nparts GREATER 2)
      list(GET parts 2 defs)
      string(REPLACE "," ";" defs "${defs}")
      foreach(d ${defs})
        list(APPEND define_flags -D${d})
      endforeach()
    endif()
    get_filename_component(abs ${src} ABSOLUTE)
    get_filename_component(name ${src} NAME_WE)
    get_filename_component(ext ${src} LAST_EXT)
    string(SUBSTRING ${ext} 1 -1 stage)
    set(symbol ${name}${variant}_${stage})
    set(spv_header ${out_dir}/${symbol}.spv.inc)
    set(header ${out_dir}/${symbol}.h)
    add_custom_command(
      OUTPUT ${spv_header}
      COMMAND Vulkan::glslangValidator --quiet --target-env vulkan1.3 ${include_flags} ${define_flags}
              --depfile ${spv_header}.d --vn ls_spirv_raw_${symbol} -o ${spv_header} ${abs}
      DEPENDS ${abs}
      DEPFILE ${spv_header}.d
      COMMENT "GLSL -> SPIR-V ${name}.${stage}"
      VERBATIM)
    # Wrap glslang's array in a namespace and give it a stable name.
    add_custom_command(
      OUTPUT ${header}
      COMMAND ${CMAKE_COMMAND} -DIN=${spv_header} -DOUT=${header} -DSYMBOL=${symbol}
              -P ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/WrapSpirv.cmake
      DEPENDS ${spv_header} ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/WrapSpirv.cmake
      VERBATIM)
    list(APPEND headers ${header})
  endforeach()
  add_custom_target(${ARG_TARGET}_gen DEPENDS ${headers})
  add_library(${ARG_TARGET} INTERFACE)
  add_dependencies(${ARG_TARGET} ${ARG_TARGET}_gen)
  target_include_directories(${ARG_TARGET} INTERFACE ${out_dir})
endfunction()
