// Seed 002's planes' own descriptor bindings and specialisation-constant ids, written once for
// both languages as shaders/shared/bindings.h's are: its shaders include it, passes/planes/
// includes it as "shaders/planes/planes_bindings.h". Only #defines and comments.
#ifndef LS_PLANES_BINDINGS_H
#define LS_PLANES_BINDINGS_H

#define LS_BINDING_PLANE_SUM 2  // plane_resolve.frag

// From 10 up, past frame.glsl's.
#define LS_SPEC_PLANES_CHANNELS 10  // planes.frag
#define LS_SPEC_PLANES_DITHER 11
#define LS_SPEC_RESOLVE_CHANNELS 10  // plane_resolve.frag
#define LS_SPEC_RESOLVE_BLUR_RADIUS 11
#define LS_SPEC_RESOLVE_CLOSED_FORM_OUTSIDE_SLAB 12

#endif
