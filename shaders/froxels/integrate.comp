#version 450
#extension GL_GOOGLE_include_directive : require
// Front-to-back integration along each froxel column (Hillaire 2015's energy-conserving form):
// a slice of thickness d along the column's ray, whose froxel holds in-scattering S per unit
// length, adds T S (1 - exp(-betaT d)) / betaT to Lin (its in-scattering integrated against its
// own extinction, not S d) and multiplies the transmittance T by exp(-betaT d). Each froxel of the
// result holds Lin and T from the camera to its slice's far end; T is one value, the mean of the
// three channels, as engines keep it. Slice 0 starts at the camera.
#include "froxel_grid.glsl"
#include "math.glsl"
#include "medium.glsl"
#include "froxel_bindings.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = LS_BINDING_FROXEL_SCATTERING, rgba32f) uniform readonly image3D scattering;
#if LS_FROXEL_PIXEL_HISTORY
// The per-pixel history's apply integrates, in a still frame (pc.shift.w), this frame's samples at
// its offset columns, which it gathers per pixel, not their blend with the frames before.
layout(binding = LS_BINDING_FROXEL_SAMPLES, rgba32f) uniform readonly image3D samples;
vec3 sliceScattering(ivec3 f) {
    return pc.shift.w > 0.5 ? imageLoad(samples, f).rgb : imageLoad(scattering, f).rgb;
}
#else
vec3 sliceScattering(ivec3 f) { return imageLoad(scattering, f).rgb; }
#endif
layout(binding = LS_BINDING_FROXEL_INTEGRATED, rgba16f) uniform writeonly image3D integrated;

void main() {
    ivec3 g = ivec3(pc.grid.xyz);
    ivec2 c = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(c, g.xy))) return;
    // The column's centre ray: its length per unit of camera-space z.
    vec3 dir = rayDirection(columnNdc(vec2(c), vec2(0.5)));
    float perZ = 1.0 / axisCosine(dir);
    vec3 betaT = frame.betaT.rgb;
    vec3 lin = vec3(0.0), T = vec3(1.0);
    float start = 0.0;
    for (int k = 0; k < g.z; ++k) {
        float end = sliceZ(float(k + 1));
        float d = (end - start) * perZ;
        vec3 S = sliceScattering(ivec3(c, k));
        // A non-uniform medium: the slice's optical depth along the column's ray, exact, stands
        // for its length (its scattering and extinction both scale with m: dT = -betaT m T ds).
        float depth = kMedia != 0 ? opticalDepth(frame.cameraPos.xyz + (start * perZ) * dir, dir, d) : d;
        vec3 sliceT = exp(-betaT * depth);
        lin += T * S * attenuatedLength(betaT, depth);
        T *= sliceT;
        start = end;
        imageStore(integrated, ivec3(c, k), vec4(clamp(lin * pc.slices.w, vec3(0.0), vec3(65504.0)), dot(T, vec3(1.0 / 3.0))));
    }
}
