#version 330 core
// Lines, triangles and text: position and colour per vertex, one matrix.
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec4 a_color;
uniform mat4 u_mvp;
uniform float u_clip_lo, u_clip_hi;  // GL heights kept: the time window (renderer.cpp)
out float gl_ClipDistance[2];
out vec4 v_color;
void main() {
    v_color = a_color;
    gl_Position = u_mvp * vec4(a_pos, 1.0);
    gl_ClipDistance[0] = a_pos.y - u_clip_lo;
    gl_ClipDistance[1] = u_clip_hi - a_pos.y;
}
