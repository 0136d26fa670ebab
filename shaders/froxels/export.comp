#version 450
#extension GL_GOOGLE_include_directive : require
// The integrated grid copied into the engine's 3D image (FrameDescription::volumeOut) as the header
// promises it: Lin in rgb at its true scale (the grid keeps it times the storage scale, which
// volumeOut's readers cannot know), capped at float16's largest finite value, and the
// transmittance in a. Texel for texel: froxel k holds Lin and T from the camera to slice k's far
// end.
#include "froxel_grid.glsl"
#include "froxel_bindings.h"
layout(local_size_x = 32, local_size_y = 4, local_size_z = 1) in;  // as the temporal blend
layout(binding = LS_BINDING_FROXEL_INTEGRATED, rgba16f) uniform readonly image3D integrated;
layout(binding = LS_BINDING_FROXEL_VOLUME_OUT, rgba16f) uniform writeonly image3D volumeOut;

void main() {
    ivec3 f = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(f, ivec3(pc.grid.xyz)))) return;
    vec4 g = imageLoad(integrated, f);
    imageStore(volumeOut, f, vec4(min(max(g.rgb, vec3(0.0)) / pc.slices.w, vec3(65504.0)), g.a));
}
