#version 450
#extension GL_GOOGLE_include_directive : require
// What a frame's later light's unwarp and fix-up draw (kWedgeVertices vertices). Where its lines
// take a window of the border (epipolar.window.z: a spot seen from outside its cone, a light off
// the screen), the wedge from the light's screen point through the window's slices that a lit
// pixel may read, half a slice wider each side than the pixels any of them serves, as a fan of five
// triangles; a pixel outside it has no sample and no Lin, and neither pass pays for it. Otherwise
// the viewport's one triangle (fullscreen.vert's), the others empty.
#include "epipolar_geometry.glsl"

void main() {
    int v = gl_VertexIndex;
    if (epipolar.window.z == 0.0) {
        int k = v < 3 ? v : 0;
        gl_Position = vec4(vec2((k << 1) & 2, k & 2) * 2.0 - 1.0, 0.0, 1.0);
        return;
    }
    vec2 light = frame.lightScreen.xy;
    // The window's border coordinates u (4 a turn): a pixel between border slices g and g + 1 lies
    // between u = (g + 0.5) / border * 4 and (g + 1.5) / border * 4, and the slices a lit pixel
    // reads (the window's past its step's rounding) serve g from their first - 1 to their last.
    float border = epipolar.window.y;
    float from = epipolar.window.x + epipolar.window.w;  // the first slice a lit pixel reads
    float ua = (from - 1.0) / border * 4.0;
    float ub = (from + epipolar.window.z + 1.0) / border * 4.0;
    int edge;
    int corner = v % 3;
    if (corner == 0) {
        // Two pixels behind the light, away from the window's middle: a pixel within a pixel of
        // the light's point, whose direction from it rounding decides, is inside the wedge.
        vec2 middle = borderPoint(mod(0.5 * (ua + ub), 4.0), edge) - light;
        vec2 inPixels = middle * frame.screenSize.xy;
        vec2 back = inPixels / max(length(inPixels), 1e-6) * 4.0 * frame.screenSize.zw;  // 2 pixels
        gl_Position = vec4(light - back, 0.0, 1.0);
        return;
    }
    // The fan's points: the window's start, each boundary corner within it, then its end (the
    // triangles past the end are empty).
    int i = v / 3 + corner - 1;
    float u = i == 0 ? ua : min(floor(ua) + float(i), ub);
    vec2 b = borderPoint(mod(u, 4.0), edge);
    // Twice as far from the light: past the boundary, so that its own pixels are inside.
    gl_Position = vec4(light + (b - light) * 2.0, 0.0, 1.0);
}
