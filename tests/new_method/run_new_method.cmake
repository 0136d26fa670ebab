# A method is its two folders (#37). A copy of the source tree gets null_method.patch: a method
# that writes the same Lin in every pixel, in passes/null/ and shaders/null/, plus at most three
# lines elsewhere (its line in methods.inc, its ls_add_method line, the include of its settings
# header). The copy's lightscatter program is built alone, and the method must then be everywhere
# a method is: --help and the usage of --settings (from methodInfo() and its field table), a
# settings file nested or dotted, budget, bench's methods, sweeps and configurations, the viewer's
# panel, the refusal its caps imply, and a render whose Lin is the value it was given.
#   cmake -DSOURCE_DIR=... -DWORK_DIR=... -DPATCH=... -DCHECK=test_constant_lin [-DJOBS=N]
#         [-DCXX=...] [-DGENERATOR=...] -P run_new_method.cmake
cmake_minimum_required(VERSION 3.25)
foreach(var SOURCE_DIR WORK_DIR PATCH CHECK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_new_method.cmake: ${var} is not set")
  endif()
endforeach()
if(NOT DEFINED JOBS)
  set(JOBS 2)
endif()
set(tree ${WORK_DIR}/tree)
set(build ${WORK_DIR}/build)
set(run ${WORK_DIR}/run)
find_program(GIT git REQUIRED)

# Runs a command in `run`; fails the test with its output unless it exits 0.
function(must)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${run} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " line "${ARGN}")
    message(FATAL_ERROR "failed (${rc}): ${line}\n${out}")
  endif()
  set(output "${out}" PARENT_SCOPE)
endfunction()

function(expect_in text fragment what)
  string(FIND "${text}" "${fragment}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${what} does not hold '${fragment}':\n${text}")
  endif()
endfunction()

# The copy: the files git knows (tracked, or new and not ignored), without the tests, the docs and
# the benchmark's files, which a method's build does not read.
file(REMOVE_RECURSE ${tree} ${run})
file(MAKE_DIRECTORY ${tree} ${run})
execute_process(COMMAND ${GIT} ls-files --cached --others --exclude-standard
                WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE files RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "git ls-files failed in ${SOURCE_DIR}: the test copies a git checkout")
endif()
string(REPLACE "\n" ";" files "${files}")
foreach(f IN LISTS files)
  if(f STREQUAL "" OR f MATCHES "^(tests|docs|bench|scenes)/" OR NOT EXISTS ${SOURCE_DIR}/${f})
    continue()
  endif()
  get_filename_component(dir ${f} DIRECTORY)
  file(COPY ${SOURCE_DIR}/${f} DESTINATION ${tree}/${dir})
endforeach()
foreach(d passes/null shaders/null)
  if(EXISTS ${tree}/${d})
    message(FATAL_ERROR "${d} exists before the patch: the test adds it")
  endif()
endforeach()

# The patch, applied in a repository of its own (not the checkout the copy sits in), and what it
# changes outside the method's two folders.
execute_process(COMMAND ${GIT} init -q WORKING_DIRECTORY ${tree})
execute_process(COMMAND ${GIT} apply --numstat ${PATCH} WORKING_DIRECTORY ${tree}
                OUTPUT_VARIABLE numstat RESULT_VARIABLE rc)
string(REPLACE "\n" ";" numstat "${numstat}")
set(outside 0)
set(inside 0)
foreach(row IN LISTS numstat)
  if(row MATCHES "^([0-9]+)\t([0-9]+)\t(.+)$")
    math(EXPR lines "${CMAKE_MATCH_1} + ${CMAKE_MATCH_2}")
    set(path "${CMAKE_MATCH_3}")
    if(path MATCHES "^(passes|shaders)/null/")
      math(EXPR inside "${inside} + ${lines}")
    else()
      math(EXPR outside "${outside} + ${lines}")
      message(STATUS "outside the method's folders: ${path}, ${lines} line(s)")
    endif()
  endif()
endforeach()
if(inside EQUAL 0)
  message(FATAL_ERROR "${PATCH} adds nothing to passes/null or shaders/null")
endif()
if(outside GREATER 3)
  message(FATAL_ERROR "${PATCH} changes ${outside} lines outside passes/null and shaders/null: a "
                      "method may take at most 3 (methods.inc, passes/CMakeLists.txt, settings.h)")
endif()
execute_process(COMMAND ${GIT} apply ${PATCH} WORKING_DIRECTORY ${tree} RESULT_VARIABLE rc
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${PATCH} does not apply to the tree (update its context lines):\n${err}")
endif()
message(STATUS "the patch: ${inside} lines in the method's folders, ${outside} outside")

# The lightscatter program alone, as the first README command builds it.
set(configure ${CMAKE_COMMAND} -S ${tree} -B ${build} -DCMAKE_BUILD_TYPE=Release -DLS_WERROR=ON
              -DLS_BUILD_TESTS=OFF -DLS_INSTALL=OFF)
if(DEFINED CXX)
  list(APPEND configure -DCMAKE_CXX_COMPILER=${CXX})
endif()
if(DEFINED GENERATOR)
  list(APPEND configure -G ${GENERATOR})
endif()
must(${configure})
must(${CMAKE_COMMAND} --build ${build} --target lightscatter -j${JOBS})
set(cli ${build}/host_example/lightscatter)
set(scenes ${SOURCE_DIR}/scenes)

# --help's methods (methodInfo()) and --settings' fields (the method's table).
must(${cli} --help)
if(NOT output MATCHES "[ \n]null[,)]")
  message(FATAL_ERROR "lightscatter --help lists no method null:\n${output}")
endif()
must(${cli} render --help)
expect_in("${output}" "null.value" "lightscatter render --help")

# A settings file nested by the method's member, then one with the dotted name; each render's Lin
# is the value it gave, under validation.
file(WRITE ${run}/nested.json [=[{"null": {"value": 0.5}}]=])
file(WRITE ${run}/dotted.json [=[{"null.value": 2}]=])
foreach(case nested:0.5 dotted:2)
  string(REPLACE ":" ";" case ${case})
  list(GET case 0 name)
  list(GET case 1 value)
  must(${cli} render ${scenes}/point_fog.json --method null --settings ${name}.json --size 64x36
       --out ${name}.exr --inscatter ${name}-lin.exr --timings ${name}.json.timings --validation)
  file(READ ${run}/${name}.json.timings timings)
  string(JSON ran GET "${timings}" methodRan)
  if(NOT ran STREQUAL "null")
    message(FATAL_ERROR "render --method null ran ${ran}")
  endif()
  must(${CHECK} ${name}-lin.exr ${value})
  message(STATUS "${output}")
endforeach()

# A shadowed light is refused by what its caps say, naming the methods that take one.
execute_process(COMMAND ${cli} render ${scenes}/atrium.json --method null --size 32x18
                        --out refused.png WORKING_DIRECTORY ${run} RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(rc EQUAL 0 OR EXISTS ${run}/refused.png)
  message(FATAL_ERROR "a shadowed light rendered with null, which samples no shadow map:\n${out}")
endif()
expect_in("${out}" "null" "the refusal of a shadowed light")
expect_in("${out}" "epipolar" "the refusal of a shadowed light")

# budget, with the method's settings in its header line.
must(${cli} budget --method null --profile balanced --json)
string(JSON method GET "${output}" 0 method)
if(NOT method STREQUAL "null")
  message(FATAL_ERROR "budget --method null budgeted ${method}:\n${output}")
endif()
must(${cli} budget --method null --profile balanced)
expect_in("${output}" "null.value 0.25" "budget --method null")

# bench: in methods, a sweep of its field, and a configuration setting it nested.
file(WRITE ${run}/bench.json [=[{"frames": 1, "warmup": 0, "size": "32x18", "measureError": false,
  "scenes": ["SCENES/point_fog.json"], "methods": ["null"], "profiles": ["balanced"],
  "sweeps": {"null.value": [0.125, 0.5]},
  "configurations": [{"label": "nested", "method": "null", "null": {"value": 2}}]}]=])
file(READ ${run}/bench.json config)
string(REPLACE "SCENES" "${scenes}" config "${config}")
file(WRITE ${run}/bench.json "${config}")
must(${cli} bench --config bench.json --out bench)
file(STRINGS ${run}/bench/bench.csv rows)
foreach(label ",null,profiles,null," ",null.value=0.125,null.value,null," ",null.value=0.5,null.value,null,"
              ",nested,configurations,null,")
  expect_in("${rows}" "${label}" "bench.csv")
endforeach()

# The viewer's panel sets the field through its own edit, and the next frame's report shows it.
find_program(XVFB_RUN xvfb-run)
if(NOT XVFB_RUN)
  message(FATAL_ERROR "xvfb-run is missing (Debian package xvfb)")
endif()
file(WRITE ${run}/script.json
     [=[[{"method": "null", "profile": "custom", "settings": {"null.value": 0.75}}]]=])
# The X authority file in the run's folder, not in xvfb-run's temporary folder (see
# tests/host/cli_runner.h).
must(${XVFB_RUN} -a -f ${run}/.xvfb-authority -s "-screen 0 640x480x24" ${cli} view ${scenes}/point_fog.json --size 64x36
     --frames 3 --panel-script script.json --report-log log.json --validation)
file(READ ${run}/log.json log)
string(JSON last LENGTH "${log}")
math(EXPR last "${last} - 1")
string(JSON shown GET "${log}" ${last} lights 0 settings null.value)
string(JSON method GET "${log}" ${last} lights 0 method)
if(NOT method STREQUAL "null" OR NOT shown STREQUAL "0.75")
  message(FATAL_ERROR "the panel set null.value 0.75; the report shows ${method}, ${shown}:\n${log}")
endif()
message(STATUS "null is in --help, settings files, budget, bench and the panel, and renders")
