// The fields of the froxel temporal blend's push block (temporal.comp), written once for both
// languages as froxel_push_fields.h is: grid and slices as there, then the frame before's.
LS_VEC4 grid;              // as froxel_push_fields.h
LS_VEC4 slices;            // as froxel_push_fields.h
LS_MAT4 previousViewProj;  // world -> the frame before's clip
LS_VEC4 previousSlices;    // x: its first slice's start, y: its far distance, z: log(y / x), w: 1
                           // when the history holds the frame before's grid
// x: the history's weight; y: 1 when a light changed since the frame before; z: how far outside
// this frame's neighbourhood box (in box widths) such a light's history is dropped; w: 1 where the
// history is kept as it is (the per-pixel history's still frames)
LS_VEC4 blend;
