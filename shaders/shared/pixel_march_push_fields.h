// The fields of pixel_march.frag's push block, written once for both languages: the shader declares
// its block with them, passes/shared/pixel_march.cpp its two C++ structs, each defining LS_UINT
// first, and LS_PIXEL_MARCH_COMPOSITES 1 for the build that composites (the fix-up's).
LS_UINT maxSteps;  // 0: one step per texel
#if LS_PIXEL_MARCH_COMPOSITES
LS_UINT addOnly;  // a frame's later light
#endif
