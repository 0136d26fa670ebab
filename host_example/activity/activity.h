#pragma once
// What the program is doing, kept so that when host memory runs out the one line it can still
// print says while doing what ("out of host memory while loading x.gltf").
#include <string>

namespace host {

class Activity {
  public:
    explicit Activity(std::string what);  // e.g. "loading /path/model.glb"
    ~Activity();
    Activity(const Activity&) = delete;
    Activity& operator=(const Activity&) = delete;
};

// The innermost activity of this thread, or "" when there is none. Allocates nothing: safe to
// call after std::bad_alloc, as long as the Activity objects are still alive.
const char* currentActivity();

}  // namespace host
