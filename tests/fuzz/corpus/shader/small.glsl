#version 450
layout(local_size_x = 8) in;
layout(std430, binding = 0) buffer O { float o[]; };
void main() { o[gl_GlobalInvocationID.x] = 1.0; }
