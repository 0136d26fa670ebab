// Seed 003's march's own specialisation-constant ids, written once for both languages as
// shaders/shared/bindings.h's are: cone_march.frag includes it, passes/cone_march/ includes it as
// "shaders/cone_march/cone_march_bindings.h". Only #defines and comments.
#ifndef LS_CONE_MARCH_BINDINGS_H
#define LS_CONE_MARCH_BINDINGS_H

// From 10 up, past frame.glsl's.
#define LS_SPEC_CONE_SAMPLES 10  // cone_march.frag
#define LS_SPEC_CONE_LIMITED 11
#define LS_SPEC_CONE_JITTER 12

#endif
