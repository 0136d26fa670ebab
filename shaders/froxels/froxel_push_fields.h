// The fields of the froxel passes' push block, written once for both languages: froxel_grid.glsl
// declares the block with them, passes/froxels/froxel_nodes.cpp the C++ struct, each defining
// LS_VEC4 first. Counts are floats (exact below 2^24).
LS_VEC4 grid;     // x: columns, y: rows, z: depth slices, w: pixels per froxel on x and y
LS_VEC4 slices;   // x: the first slice's start (camera-space z, the near plane), y: the last one's
                  // end (the froxel far distance), z: log(y / x), w: the integrated grid's storage
                  // scale (its Lin is stored times w, loaded times 1 / w)
LS_VEC4 jitter;   // xyz: where in its froxel each froxel is sampled, in [0, 1) (0.5: the centre);
                  // the temporal mode: the frame's step of every froxel's own point, and w: the
                  // share of the froxel the points spread over (froxel_jitter.glsl)
LS_VEC4 columns;  // inject: xy the first column and row the light reaches, zw one past the last
LS_VEC4 shift;    // xy: the whole grid's offset this frame, in froxels (the per-pixel history's
                  // sub-froxel steps; 0 otherwise); z: the share of jitter.w each froxel's own
                  // point takes across the column (1; 0 with the per-pixel history); w: 1 in a
                  // still frame of the per-pixel history (its apply integrates this frame's
                  // samples), else 0
