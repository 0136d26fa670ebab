#version 450
layout(local_size_x = 64) in;
layout(binding = 0) writeonly buffer Out { uint values[]; };
layout(push_constant) uniform Push { uint count; } pc;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < pc.count) values[i] = i + 1u;
}
