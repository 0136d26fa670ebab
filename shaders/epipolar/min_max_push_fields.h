// The fields of min_max_next_level.comp's push block, written once for both languages: the shader
// declares its block with them, passes/epipolar/min_max_tree_nodes.cpp the C++ struct, each
// defining LS_INT first.
LS_INT level;  // the level this pass builds (2 .. log2 n)
LS_INT n;      // the line's samples: the shadow-map size
LS_INT faces;  // a point light's cube faces in view, a bit each (EpipolarConstants::cubeFaces)
