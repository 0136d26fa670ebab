# What the plugin's integration costs render_pass_engine.cpp (cmake -P): the lines that exist only
# in the build with the plugin. Those are the lines inside its `#if LS_WITH_PLUGIN` blocks (code and
# comments; the #if and #endif lines, which only the two builds need, are counted apart) and the
# lines outside them that read LS_WITH_PLUGIN (a ternary: they differ between the builds). The
# test's own lines in the blocks (marked "// the test's checks": the comparison with the other
# build's image) are counted apart too. Fails when the rest passes MAX_LINES.
file(STRINGS ${SOURCE} lines)
set(inside FALSE)
foreach(kind code comments directives differing test)
  set(${kind} 0)
endforeach()
foreach(line IN LISTS lines)
  if(line MATCHES "^#if LS_WITH_PLUGIN")
    if(inside)
      message(FATAL_ERROR "a nested #if LS_WITH_PLUGIN block")
    endif()
    set(inside TRUE)
    math(EXPR directives "${directives} + 1")
  elseif(inside AND line MATCHES "^#(if|else|elif)")
    message(FATAL_ERROR "#if, #else or #elif inside an #if LS_WITH_PLUGIN block: not counted here")
  elseif(inside AND line MATCHES "^#endif")
    set(inside FALSE)
    math(EXPR directives "${directives} + 1")
  elseif(inside AND line MATCHES "// the test's checks")
    math(EXPR test "${test} + 1")
  elseif(inside AND line MATCHES "^ *//")
    math(EXPR comments "${comments} + 1")
  elseif(inside AND NOT line STREQUAL "")
    math(EXPR code "${code} + 1")
  elseif(NOT inside AND line MATCHES "LS_WITH_PLUGIN" AND NOT line MATCHES "^ *//")
    math(EXPR differing "${differing} + 1")
  endif()
endforeach()
math(EXPR total "${code} + ${comments} + ${differing}")
message(STATUS "the plugin's lines: ${code} of code and ${comments} of comments in the "
               "#if LS_WITH_PLUGIN blocks, ${differing} more that differ between the builds: "
               "${total} in all (at most ${MAX_LINES}); besides, ${test} lines of the test's checks and "
               "${directives} #if/#endif lines")
if(total GREATER MAX_LINES)
  message(FATAL_ERROR "the plugin's integration takes ${total} lines, more than ${MAX_LINES}")
endif()
