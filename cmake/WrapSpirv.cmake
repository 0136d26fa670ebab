# Turns glslang's --vn output into a header with one namespaced constexpr array.
file(READ ${IN} body)
string(REGEX REPLACE "const uint32_t ls_spirv_raw_[A-Za-z0-9_]+\\[\\]"
       "inline constexpr uint32_t ${SYMBOL}[]" body "${body}")
string(REGEX REPLACE "[^\n]*//[^\n]*\n" "" body "${body}")
string(REPLACE "#pragma once" "" body "${body}")
file(WRITE ${OUT}.tmp "#pragma once\n#include <cstdint>\nnamespace ls_spirv {\n${body}\n}  // namespace ls_spirv\n")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
