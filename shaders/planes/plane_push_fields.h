// The fields of the planes' push block, written once for both languages: plane_push.glsl
// declares the block with them, passes/planes/plane_geometry.h the C++ struct PlanePush, each
// defining LS_MAT4, LS_VEC4 and LS_INIT (a C++ default member value; nothing in GLSL) before
// including this. Only mat4 and vec4 members: the push block's layout is C++'s.
LS_MAT4 viewToWorld LS_INIT(1.0f);
// xy: the planes' view-space x, y minimum; z: view depth of the first plane's front; w: the
// spacing between planes along the view axis (m)
LS_VEC4 boxMin LS_INIT(0.0f);
LS_VEC4 boxMax
    LS_INIT(0.0f);  // xy: maximum; z: the number of planes; w: 4 / the 8-bit target's range
LS_VEC4 noise LS_INIT(0.0f);  // xy: layer 1's scroll, zw: layer 2's (tiles)
// x: ambient (1/m^2), y: noise amplitude, z: 1 / noise scale, w: the farthest a ray reaches (the
// sky distance)
LS_VEC4 params LS_INIT(0.0f);
