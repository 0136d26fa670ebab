#version 450
// Forward shading of the host engine: Lambertian surfaces lit by the scene's one light (irradiance
// as docs/model.md defines it, through the shadow map when there is one) plus a constant ambient
// irradiance. The result is linear radiance, which the plugin then attenuates and adds Lin to.
//
// The light type is a specialisation constant, not a uniform: lavapipe (Mesa 22.3) recompiles,
// and never frees, a shader for every draw whose branch conditions depend on uniform values alone
// (its "inline uniforms" path), which made memory grow by megabytes per frame
// (docs/reliability.md).
layout(location = 0) in vec3 worldPos;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec2 uv;
layout(location = 0) out vec4 outColor;

layout(constant_id = 0) const int LIGHT_TYPE = 0;  // 0 directional, 1 spot, 2 point

layout(push_constant) uniform Push {
    mat4 viewProj;
    vec4 baseColor;
} pc;

layout(std140, binding = 0) uniform Lighting {
    mat4 lightViewProj;
    vec4 lightPos;        // xyz
    vec4 lightDir;        // xyz; w: cos(half angle)
    vec4 lightIntensity;  // rgb; w: range
    vec4 betaT;           // rgb; w: r0
    vec4 ambient;         // rgb
    vec4 shadowInfo;      // x: size, y: depth bias (0: the shadow pass biases instead)
} light;
layout(binding = 1) uniform sampler2D baseColorTexture;
#if HOST_SHADOWED
layout(binding = 2) uniform sampler2D shadowMap;

float shadowTexel(ivec2 p) {
    int size = int(light.shadowInfo.x);
    return texelFetch(shadowMap, clamp(p, ivec2(0), ivec2(size - 1)), 0).r;
}

float visibility(vec3 p) {
    vec4 clip = light.lightViewProj * vec4(p, 1.0);
    if (clip.w <= 0.0) return 0.0;
    vec3 ndc = clip.xyz / clip.w;
    vec2 suv = ndc.xy * 0.5 + 0.5;
    if (any(lessThan(suv, vec2(0.0))) || any(greaterThan(suv, vec2(1.0)))) return 1.0;
    float z = ndc.z - light.shadowInfo.y;  // the shadow map keeps standard depth
    vec2 t = suv * light.shadowInfo.x - 0.5;
    ivec2 i = ivec2(floor(t));
    vec2 f = t - floor(t);
    vec4 lit = vec4(z <= shadowTexel(i), z <= shadowTexel(i + ivec2(1, 0)),
                    z <= shadowTexel(i + ivec2(0, 1)), z <= shadowTexel(i + ivec2(1, 1)));
    return mix(mix(lit.x, lit.y, f.x), mix(lit.z, lit.w, f.x), f.y);
}
#else
float visibility(vec3 p) { return 1.0; }
#endif

void main() {
    vec3 albedo = pc.baseColor.rgb * texture(baseColorTexture, uv).rgb;
    vec3 n = normalize(worldNormal);
    if (!gl_FrontFacing) n = -n;  // glTF meshes may be seen from either side
    vec3 toLight;
    vec3 irradiance = light.lightIntensity.rgb;
    if (LIGHT_TYPE == 0) {
        toLight = -light.lightDir.xyz;
    } else {
        vec3 d = light.lightPos.xyz - worldPos;
        float r = length(d);
        toLight = d / max(r, 1e-6);
        float r0 = light.betaT.w;
        irradiance *= exp(-light.betaT.rgb * r) / (r * r + r0 * r0);
        if (LIGHT_TYPE == 1 && (dot(-toLight, light.lightDir.xyz) < light.lightDir.w || r > light.lightIntensity.w))
            irradiance = vec3(0.0);
    }
    float cosine = max(dot(n, toLight), 0.0);
    vec3 radiance = albedo / 3.14159265 * (irradiance * cosine * visibility(worldPos) + light.ambient.rgb);
    outColor = vec4(radiance, 1.0);
}
