// Colored shafts (seed 000): a light-space color texture multiplies what reaches each point.
// Needs `lightColorMap` (sampler2D, linear) declared by the including shader when LS_LIGHT_COLOR.
#ifndef LS_LIGHT_COLOR_GLSL
#define LS_LIGHT_COLOR_GLSL

vec3 lightColorAt(vec2 uv) {
#if LS_LIGHT_COLOR
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return vec3(1.0);
    return textureLod(lightColorMap, uv, 0.0).rgb;
#else
    return vec3(1.0);
#endif
}

#endif
