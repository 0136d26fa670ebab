// The slice planes' per-frame placement (passes/slices/slice_geometry.h, SlicePush), pushed each
// frame: where the planes are, how much of Lin each one carries, and the noise's scroll.
#ifndef LS_SLICE_PUSH_GLSL
#define LS_SLICE_PUSH_GLSL

layout(push_constant) uniform SlicePush {
    mat4 viewToWorld;
    vec4 boxMin;  // xy: the planes' view-space x, y minimum; z: view depth of the first plane's
                  // front; w: the spacing between planes along the view axis (m)
    vec4 boxMax;  // xy: maximum; z: the number of planes; w: 4 / the 8-bit target's range
    vec4 noise;   // xy: layer 1's scroll, zw: layer 2's (tiles)
    vec4 params;  // x: ambient (1/m^2), y: noise amplitude, z: 1 / noise scale, w: the farthest a
                  // ray reaches (the sky distance)
} slice;

#endif
