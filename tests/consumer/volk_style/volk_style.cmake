# The engine that links no Vulkan loader (volk_style_engine.cpp): compiled with VK_NO_PROTOTYPES,
# it opens libvulkan.so.1 itself. It links the plugin and libdl, and nothing of Vulkan's but its
# headers; run_consumer.cmake checks that the executable does not need libvulkan.
add_executable(volk_style_engine ${CMAKE_CURRENT_LIST_DIR}/volk_style_engine.cpp)
target_compile_definitions(volk_style_engine PRIVATE VK_NO_PROTOTYPES)
target_link_libraries(volk_style_engine PRIVATE lightscatter::plugin ${CMAKE_DL_LIBS})
target_compile_options(volk_style_engine PRIVATE -Wall -Wextra -Wpedantic -Wconversion -Werror
                       -Wno-missing-field-initializers)
set_target_properties(volk_style_engine PROPERTIES NO_SYSTEM_FROM_IMPORTED ON)
# Debian's toolchain links --as-needed, which would drop a loader linked but unused from NEEDED: the
# check is to see every library the link line names.
target_link_options(volk_style_engine PRIVATE -Wl,--no-as-needed)
