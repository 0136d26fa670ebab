# The consumer engine, shared by both consumer projects: docs/integration.md's example
# (tests/plugin/readme_example.cpp, compiled as the engine's own code) in a shared library of the
# engine's, and the headless engine that runs it. The example's folder holds no lightscatter header:
# lightscatter.h comes from the target, the installed tree or the source tree.
set(ls_consumer_tests ${CMAKE_CURRENT_LIST_DIR}/../..)
set(CMAKE_CXX_STANDARD 17)  # the public header's floor
set(CMAKE_CXX_STANDARD_REQUIRED ON)
set(CMAKE_CXX_EXTENSIONS OFF)

# A shared library of the engine with the plugin inside (static package: the plugin's archives must
# be position-independent for this to link).
add_library(engine_effects SHARED ${ls_consumer_tests}/plugin/readme_example.cpp)
target_include_directories(engine_effects PUBLIC ${ls_consumer_tests}/plugin)
# The engine's own Vulkan calls go through the loader it links; the plugin binds no vk* symbol and
# needs none (it loads its entry points at run time).
find_package(Vulkan 1.3 REQUIRED)
target_link_libraries(engine_effects PUBLIC lightscatter::plugin Vulkan::Vulkan)
target_compile_options(engine_effects PRIVATE -Wall -Wextra -Wpedantic -Wconversion -Werror)
target_link_options(engine_effects PRIVATE -Wl,--no-undefined)

add_executable(headless_engine ${CMAKE_CURRENT_LIST_DIR}/headless_engine.cpp)
target_link_libraries(headless_engine PRIVATE engine_effects)
target_compile_options(headless_engine PRIVATE -Wall -Wextra -Wpedantic -Werror -Wno-missing-field-initializers)
# The installed header is compiled with the engine's warnings too, not as a system header.
set_target_properties(engine_effects headless_engine PROPERTIES NO_SYSTEM_FROM_IMPORTED ON)
