// The fields of the froxel apply's push block (apply.comp), written once for both languages as
// froxel_push_fields.h is: grid, slices and shift as there, then the per-pixel history's.
LS_VEC4 grid;    // as froxel_push_fields.h
LS_VEC4 slices;  // as froxel_push_fields.h
LS_VEC4 shift;   // as froxel_push_fields.h
// The per-pixel history: x: the width (sigma, in froxels) of the weight a pixel gives this frame's
// nearest column, by its distance to it; y: the most weight the history carries; z: 1 when nothing
// moved since the frame before, whose pixels the history holds (they gather this frame's columns),
// 0 when it starts again from this frame's trilinear fetch, with weight w; w: that weight
LS_VEC4 history;
