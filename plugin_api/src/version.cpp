// The library's version, as the header it was built with states it (the CMake package's version is
// read from the same lines, CMakeLists.txt).
#include <lightscatter/lightscatter.h>

namespace lightscatter {

Version version() {
    return {LIGHTSCATTER_VERSION_MAJOR, LIGHTSCATTER_VERSION_MINOR, LIGHTSCATTER_VERSION_PATCH};
}

}  // namespace lightscatter
