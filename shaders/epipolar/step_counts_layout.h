// The layout of the ray march's step counter (DebugOptions::countSteps), written once for both
// languages: ray_march.frag adds into it, passes/epipolar/step_counts.h reads it back. One row of
// LS_COUNT_STRIDE uint32 counters per slice, in this order; the rest of a row is unused.
#define LS_COUNT_SAMPLES 0           // ray-marching samples (once each, whatever the cube face)
#define LS_COUNT_RAYS 1              // rays that cross the shadow map (once per cube face)
#define LS_COUNT_LINE_STEPS 2        // level-0 steps along the slice's line (look-ups)
#define LS_COUNT_TREE_NODES 3        // min/max tree nodes tested
#define LS_COUNT_DEGENERATE_RAYS 4   // rays marched on their own (marchFrustumSegment)
#define LS_COUNT_DEGENERATE_STEPS 5  // ... and their look-ups
#define LS_COUNT_LISTED 6            // samples the first march took from the march list
#define LS_COUNT_UNBUILT_NODES 7     // tree nodes tested that the trees pass did not build (0)
#define LS_COUNTERS 8
#define LS_COUNT_STRIDE 8
