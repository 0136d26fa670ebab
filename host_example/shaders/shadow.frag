#version 450
// Depth only: the shadow pass writes no color.
void main() {}
