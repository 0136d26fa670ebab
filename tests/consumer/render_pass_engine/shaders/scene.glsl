// The engine's per-frame uniforms (std140), shared by its shaders.
layout(set = 0, binding = 0) uniform Frame {
    mat4 viewProjection;       // camera: world -> Vulkan clip
    mat4 lightViewProjection;  // spot's shadow map: world -> clip
    vec4 lightPosition;        // xyz; w: cos(inner cone angle)
    vec4 lightDirection;       // xyz (normalised); w: cos(outer cone angle)
    vec4 lightColor;           // rgb, no units (N.L shading); w: ambient
} frame;
