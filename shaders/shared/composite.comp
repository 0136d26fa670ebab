#version 450
#extension GL_GOOGLE_include_directive : require
// color = color * exp(-betaT S) + Lin (seed 000's aerial perspective) in the engine's image, and
// optionally Lin alone into an output image, for the methods that leave Lin in a screen texture
// (epipolar composites in its unwarp and fix-up). With LS_ADD_ONLY, a frame's later light: its Lin
// is added to both. Nothing else: no tone mapping, no exposure.
#include "camera.glsl"
#include "composite_into.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = LS_BINDING_DEPTH) uniform sampler2D depthBuffer;  // the engine's depth
#if LS_WITH_LIN
layout(binding = LS_BINDING_COMPOSITE_LIN) uniform sampler2D inscatter;
#endif

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    // The frame's extent, not the image's: under dynamic resolution the engine's images are larger
    // than the frame, and what lies outside it is the engine's.
    if (any(greaterThanEqual(p, ivec2(frame.screenSize.xy)))) return;
#if LS_WITH_LIN
    vec3 lin = loadedLin(texelFetch(inscatter, p, 0).rgb);
#else
    vec3 lin = vec3(0.0);
#endif
#if defined(LS_ADD_ONLY) && LS_ADD_ONLY
    compositeInto(p, lin, 0.0, true);
#else
    compositeInto(p, lin, rayLength(pixelCameraZ(depthBuffer, p), pixelRayDirection(p)), false);
#endif
}
