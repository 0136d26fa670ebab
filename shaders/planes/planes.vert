#version 450
#extension GL_GOOGLE_include_directive : require
// Seed 002's sampling planes: instance i is a quad perpendicular to the view axis at view depth
// z_i = boxMin.z + (i + 1/2) spacing, spanning the view-space box of the light's volume (the
// trilinear placement of the seed's vertex shader). Five clip distances cut it to a spot's
// pyramid (the seed's user clip planes), so fragments outside it are never shaded.
#include "frame.glsl"
#include "plane_push.glsl"

// The point from the camera, in world axes: far from the origin a world position loses what the
// planes' spacing and a spot's cone need (frame.viewProjFromCamera).
layout(location = 0) out vec3 fromCamera;
layout(location = 1) flat out int plane;
out gl_PerVertex {
    vec4 gl_Position;
    float gl_ClipDistance[5];
};

// Signed distances to the four sides of the pyramid around the spot's cone and to its far end, for
// the point at D from the light.
void spotClipDistances(vec3 D) {
    vec3 a = frame.lightDir.xyz;
    vec3 helper = abs(a.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 r = normalize(cross(a, helper)), u = cross(r, a);
    float cosA = frame.lightDir.w;
    float tanA = sqrt(max(1.0 - cosA * cosA, 0.0)) / cosA;
    float along = dot(D, a);
    gl_ClipDistance[0] = tanA * along - dot(D, r);
    gl_ClipDistance[1] = tanA * along + dot(D, r);
    gl_ClipDistance[2] = tanA * along - dot(D, u);
    gl_ClipDistance[3] = tanA * along + dot(D, u);
    gl_ClipDistance[4] = frame.lightIntensity.w - along;
}

void main() {
    // Two triangles: corners (0,0) (1,0) (0,1) and (1,0) (1,1) (0,1).
    const vec2 corners[6] = vec2[6](vec2(0, 0), vec2(1, 0), vec2(0, 1), vec2(1, 0), vec2(1, 1), vec2(0, 1));
    vec2 c = corners[gl_VertexIndex];
    plane = gl_InstanceIndex;
    float z = placement.boxMin.z + (float(gl_InstanceIndex) + 0.5) * placement.boxMin.w;
    vec3 viewPos = vec3(mix(placement.boxMin.xy, placement.boxMax.xy, c), -z);
    fromCamera = mat3(placement.viewToWorld) * viewPos;
    gl_Position = frame.viewProjFromCamera * vec4(fromCamera, 1.0);
    if (kLightType == LIGHT_SPOT) {
        // Camera minus light first: two nearby large numbers subtract exactly.
        spotClipDistances((frame.cameraPos.xyz - frame.lightPos.xyz) + fromCamera);
    } else {
        for (int k = 0; k < 5; ++k) gl_ClipDistance[k] = 1.0;
    }
}
