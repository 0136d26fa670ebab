// The fields of the froxel apply's push block (apply.comp), written once for both languages as
// froxel_push_fields.h is: grid, slices and shift as there, then the per-pixel history's.
LS_VEC4 grid;    // as froxel_push_fields.h
LS_VEC4 slices;  // as froxel_push_fields.h
LS_VEC4 shift;   // as froxel_push_fields.h
// The per-pixel history. z: 1 when nothing moved since the frame before, whose pixels the history
// holds: they gather this frame's columns, x the width (sigma, in froxels) of the weight a pixel
// gives its nearest column by its distance to it, y the most weight the history carries. z: 0 in
// a frame that moved: y is the share of its detail a pixel keeps, carried from where the frame
// before saw its surface (0: each pixel starts again from this frame's trilinear fetch), and x the
// width as above where the camera moved (its pixels gather as they move), 0 where it did not. w:
// the weight a fetch carries; in a still frame, the weight of a pixel that a moving frame left (it
// holds that frame's fetch, apply.comp's followFetch, not a weight).
LS_VEC4 history;
// Offsets from this frame's camera -> the frame before's clip (where a pixel's surface was).
LS_MAT4 previousFromCamera;
