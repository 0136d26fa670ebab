// The fields of unwarp.frag's push block, written once for both languages: the shader declares
// its block with them, passes/epipolar/unwarp_node.cpp the C++ struct, each defining LS_INT first.
LS_INT fixup;    // 1: the fix-up serves the pixels no sample can
LS_INT addOnly;  // 1: a frame's later light (compositeInto)
