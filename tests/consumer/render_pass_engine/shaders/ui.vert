#version 450
// The UI overlay: one opaque panel in the top-left corner, as a triangle strip of 4 vertices.
void main() {
    vec2 corner = vec2(gl_VertexIndex & 1, gl_VertexIndex >> 1);
    vec2 topLeft = vec2(-0.95, -0.9), size = vec2(0.5, 0.25);  // Vulkan clip: y down
    gl_Position = vec4(topLeft + corner * size, 0.0, 1.0);
}
