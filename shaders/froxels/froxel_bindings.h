// The froxel grid's own descriptor bindings and specialisation-constant id, written once for both
// languages as shaders/shared/bindings.h's are: its shaders include it, passes/froxels/ includes
// it as "shaders/froxels/froxel_bindings.h". Only #defines and comments.
#ifndef LS_FROXEL_BINDINGS_H
#define LS_FROXEL_BINDINGS_H

#define LS_BINDING_FROXEL_SCATTERING 2   // inject.comp, integrate.comp: in-scattering per froxel
#define LS_BINDING_FROXEL_INTEGRATED 3   // integrate.comp, apply.comp: Lin and T to each froxel
#define LS_BINDING_FROXEL_HISTORY 4      // temporal.comp: the frame before's in-scattering grid
#define LS_BINDING_FROXEL_HISTORY_OUT 5  // temporal.comp: this frame's, for the next
#define LS_BINDING_FROXEL_VOLUME_OUT 12  // export.comp: the engine's 3D image (volumeOut)
#define LS_BINDING_FROXEL_NOISE 14       // inject.comp (temporal): the blue-noise tile
#define LS_BINDING_FROXEL_PIXELS 15      // apply.comp (per-pixel history): the frame before's
#define LS_BINDING_FROXEL_PIXELS_OUT 16  // apply.comp (per-pixel history): this frame's
#define LS_BINDING_FROXEL_SAMPLES 17     // integrate.comp (per-pixel history): the unblended grid
#define LS_BINDING_FROXEL_KEPT 18        // apply.comp (per-pixel history): the kept grid

// blue_noise.comp, a pass of its own: the tile's texels as uploaded, and the tile.
#define LS_BINDING_FROXEL_NOISE_TEXELS 0
#define LS_BINDING_FROXEL_NOISE_OUT 1

// From 10 up, past frame.glsl's.
#define LS_SPEC_FROXEL_FIRST_LIGHT 10  // inject.comp

#endif
