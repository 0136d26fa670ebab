#version 450
#extension GL_GOOGLE_include_directive : require
// Seed 003: every pixel marches a fixed number of samples along its ray, limited to the part the
// spot's cone and range sphere can light (kConeLimited), or over the whole ray as the seed's naive
// baseline. Each sample evaluates the integrand of docs/model.md at the sample (transmittance to
// the camera, phase function, the light's irradiance, shadow-map visibility and light color) and
// weighs it by the sample spacing (midpoint rule), optionally at a per-pixel jittered offset.
// Without shadow sampling (the seed's low-end mode) visibility is 1. A non-uniform medium weighs
// each sample by its density and the optical depth to it.
#include "camera.glsl"
#include "light_volume.glsl"
#include "math.glsl"
#include "medium.glsl"
#include "cone_march_bindings.h"
layout(binding = LS_BINDING_DEPTH) uniform sampler2D depthBuffer;  // the engine's depth
#if LS_SHADOW_MAP
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
layout(binding = LS_BINDING_SHADOW_MAP) uniform sampler2DArray shadowMap;  // six faces
#else
layout(binding = LS_BINDING_SHADOW_MAP) uniform sampler2D shadowMap;
#endif
#include "shadow.glsl"
#endif
#if LS_LIGHT_COLOR
layout(binding = LS_BINDING_LIGHT_COLOR) uniform sampler2D lightColorMap;
#endif
#include "light_color.glsl"
#include "light_at.glsl"
layout(location = 0) out vec4 outInscatter;

// Options are specialisation constants: branching on push constants alone makes lavapipe (Mesa
// 22.3) recompile the shader at every draw (docs/reliability.md).
layout(constant_id = LS_SPEC_CONE_SAMPLES) const int kSamples = 32;
layout(constant_id = LS_SPEC_CONE_LIMITED) const bool kConeLimited = true;
layout(constant_id = LS_SPEC_CONE_JITTER) const bool kJitter = false;

// Interleaved gradient noise (Jimenez 2014): a per-pixel offset in [0, 1) whose error looks like
// fine noise instead of the bands a fixed offset leaves.
float pixelNoise(vec2 p) { return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715)))); }

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 C = frame.cameraPos.xyz;
    vec3 v = pixelRayDirection(pixel);
    float S = rayLength(pixelCameraZ(depthBuffer, pixel), v);
    float t0 = 0.0, t1 = S;
    if (kConeLimited)
        lightInterval(C, v, S, t0, t1);  // clipped to the medium too
    else
        clipToMedium(C, v, t0, t1);
    vec3 lin = vec3(0.0);
    if (t0 < t1) {
        float step = (t1 - t0) / float(kSamples);
        float offset = kJitter ? pixelNoise(vec2(pixel)) : 0.5;
        // A non-uniform medium: each sample scatters m(P) times, through the optical depth from
        // the camera, taken exactly between consecutive samples.
        if (kMedia != 0) {  // an if, not the loops' condition: lavapipe keeps such a loop's body
            float tau = 0.0, last = 0.0;
            for (int i = 0; i < kSamples; ++i) {
                float s = t0 + (float(i) + offset) * step;
                vec3 P = C + s * v;
                tau += opticalDepth(C + last * v, v, s - last);
                last = s;
                float cosTheta;
                vec3 irr = lightAt(P, v, 0.0, cosTheta);
                lin += densityAt(P) * exp(-frame.betaT.rgb * tau) * phaseSum(cosTheta) * irr;
            }
        } else {
            for (int i = 0; i < kSamples; ++i) {
                float s = t0 + (float(i) + offset) * step;
                vec3 P = C + s * v;
                float cosTheta;
                vec3 irr = lightAt(P, v, 0.0, cosTheta);
                lin += exp(-frame.betaT.rgb * s) * phaseSum(cosTheta) * irr;
            }
        }
        lin *= step;
    }
    outInscatter = vec4(storedLin(lin), 1.0);
}
