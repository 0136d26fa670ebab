#pragma once
// The per-frame constants every scattering shader reads (shaders/shared/frame.glsl, std140). The
// fields are written once, in shaders/shared/frame_constants_fields.h, for this struct and for the
// shaders' uniform block.
#include <glm/glm.hpp>

#include "shaders/shared/bindings.h"

namespace ls {

struct FrameConstants {
#define LS_MAT4 glm::mat4
#define LS_VEC4 glm::vec4
#define LS_DEFAULT(x, y, z, w) \
    { x, y, z, w }
#include "shaders/shared/frame_constants_fields.h"
#undef LS_MAT4
#undef LS_VEC4
#undef LS_DEFAULT
};
// Only vec4 and mat4 members: std140 packs them as C++ does, so the sizes agree exactly when no
// member has padding of its own.
static_assert(sizeof(glm::vec4) == 16 && alignof(glm::vec4) <= 16 && sizeof(glm::mat4) == 64);
static_assert(sizeof(FrameConstants) == 4 * 64 + 19 * 16 + 6 * 64 + LS_MAX_FOG_VOLUMES * (64 + 4),
              "std140 layout of frame.glsl");

}  // namespace ls
