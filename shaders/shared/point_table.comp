#version 450
#extension GL_GOOGLE_include_directive : require
// The point-light table of seed 000 (layout in lut.glsl), computed on the GPU when the
// medium or the light's radius changes. One thread per row walks from s = +inf down to s = -inf:
//   T(h, s_a) = exp(-betaT (s_b - s_a)) T(h, s_b) + integral over [s_a, s_b],
// every factor at most 1, so nothing overflows however long the ray; each column interval is
// integrated with 8-point Gauss-Legendre in phi, where ds / (h^2 + s^2 + r0^2) = dphi / hEff.
#include "math.glsl"
layout(local_size_x = 64) in;
layout(binding = LS_BINDING_POINT_TABLE_OUT, rgba32f) uniform writeonly image2D table;

const float GL_X[4] = float[](0.1834346425, 0.5255324099, 0.7966664774, 0.9602898565);
const float GL_W[4] = float[](0.3626837834, 0.3137066459, 0.2223810345, 0.1012285363);

// The end columns stand for s = -inf and +inf; keep their tangent finite (float pi/2 lies just past
// pi/2, where tan changes sign).
float columnPhi(int col, int width) {
    float limit = 0.5 * PI - 1e-5;
    return clamp((float(col) / float(width - 1) - 0.5) * PI, -limit, limit);
}

void main() {
    int row = int(gl_GlobalInvocationID.x);
    int width = int(frame.lutInfo.y), height = int(frame.lutInfo.z);
    if (row >= height) return;
    float r0 = frame.betaT.w;
    float hEff = r0 * exp(float(row) / float(height - 1) * frame.lutInfo.x);
    float h2 = max(hEff * hEff - r0 * r0, 0.0);
    // A non-uniform medium's table holds the light's geometry and phase alone: its extinction
    // varies along the ray and the light's path, and integrate.glsl applies it per piece.
    vec3 beta = kMedia != 0 ? vec3(0.0) : frame.betaT.rgb;

    vec3 g = vec3(0.0);  // G = hEff T at s = +inf
    imageStore(table, ivec2(width - 1, row), vec4(g, 1.0));
    for (int col = width - 2; col >= 0; --col) {
        float phiA = columnPhi(col, width), phiB = columnPhi(col + 1, width);
        float sA = hEff * tan(phiA), sB = hEff * tan(phiB);
        vec3 local = vec3(0.0);
        float half_ = 0.5 * (phiB - phiA), mid = 0.5 * (phiA + phiB);
        for (int k = 0; k < 8; ++k) {
            float x = (k < 4 ? -GL_X[k] : GL_X[k - 4]);
            float phi = mid + half_ * x;
            float s = hEff * tan(phi);
            float r = sqrt(h2 + s * s);
            float cosTheta = r > 0.0 ? -s / r : 0.0;
            local += GL_W[k & 3] * phaseSum(cosTheta) * exp(-beta * ((s - sA) + r));
        }
        g = exp(-beta * (sB - sA)) * g + half_ * local;
        imageStore(table, ivec2(col, row), vec4(g, 1.0));
    }
}
