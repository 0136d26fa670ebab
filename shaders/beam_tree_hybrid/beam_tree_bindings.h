// The beam-tree methods' own descriptor binding and specialisation-constant id, written once for
// both languages as shaders/shared/bindings.h's are: their shaders include it,
// passes/beam_tree_hybrid/ includes it as "shaders/beam_tree_hybrid/beam_tree_bindings.h". Only
// #defines and comments.
#ifndef LS_BEAM_TREE_BINDINGS_H
#define LS_BEAM_TREE_BINDINGS_H

#define LS_BINDING_BEAM_TRIANGLES 3  // triangles.vert

// triangles.vert is drawn with planes.frag too: 20 is past the planes' own ids
// (shaders/planes/planes_bindings.h).
#define LS_SPEC_UNCLIPPED_DEPTH 20  // triangles.vert

#endif
