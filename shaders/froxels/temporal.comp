#version 450
#extension GL_GOOGLE_include_directive : require
// The temporal mode's blend: each froxel's in-scattering, sampled this frame at a jittered point,
// blended with the frame before's grid where that frame saw the froxel's centre (reprojected with
// its camera and its slices): lerp(this frame's, history, weight). Where the history does not
// cover it (off its frustum, or no history) the froxel keeps this frame's. The result replaces the
// grid the integration reads and is the next frame's history.
#define LS_FROXEL_TEMPORAL 1
#include "froxel_grid.glsl"
#include "froxel_bindings.h"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(binding = LS_BINDING_FROXEL_SCATTERING, rgba32f) uniform image3D scattering;
// Read as storage (GENERAL), so that the plugin's images rest in SHADER_READ_ONLY_OPTIMAL between
// frames and a graph's first frame, which finds them UNDEFINED, has a barrier to give them a layout.
layout(binding = LS_BINDING_FROXEL_HISTORY, rgba32f) uniform readonly image3D history;
layout(binding = LS_BINDING_FROXEL_HISTORY_OUT, rgba32f) uniform writeonly image3D historyOut;

// A trilinear fetch of the history at texture coordinates t (clamped to its edge froxels).
vec3 historyAt(vec3 t) {
    ivec3 g = ivec3(pc.grid.xyz);
    vec3 p = t * pc.grid.xyz - 0.5;
    ivec3 i0 = ivec3(floor(p));
    vec3 f = p - vec3(i0);
    vec3 r = vec3(0.0);
    for (int k = 0; k < 8; ++k) {
        ivec3 o = ivec3(k & 1, (k >> 1) & 1, (k >> 2) & 1);
        vec3 w = mix(1.0 - f, f, vec3(o));
        r += w.x * w.y * w.z * imageLoad(history, clamp(i0 + o, ivec3(0), g - 1)).rgb;
    }
    return r;
}

void main() {
    ivec3 f = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(f, ivec3(pc.grid.xyz)))) return;
    vec3 s = imageLoad(scattering, f).rgb;
    if (pc.previousSlices.w > 0.5) {
        vec3 v = rayDirection(columnNdc(vec2(f.xy), vec2(0.5)));
        vec3 P = frame.cameraPos.xyz + v * (sliceZ(float(f.z) + 0.5) / axisCosine(v));
        // The frame before's clip w is its camera-space z (Vulkan's perspective: w = -z_view).
        vec4 X = pc.previousViewProj * vec4(P, 1.0);
        if (X.w > pc.previousSlices.x) {
            vec2 columns = (X.xy / X.w * 0.5 + 0.5) * frame.screenSize.xy / pc.grid.w;
            float u = log(X.w / pc.previousSlices.x) / pc.previousSlices.z * pc.grid.z;
            vec3 t = vec3(columns / pc.grid.xy, u / pc.grid.z);
            if (all(greaterThanEqual(t, vec3(0.0))) && all(lessThanEqual(t, vec3(1.0))))
                s = mix(s, historyAt(t), pc.blend.x);
        }
    }
    imageStore(scattering, f, vec4(s, 0.0));
    imageStore(historyOut, f, vec4(s, 0.0));
}
