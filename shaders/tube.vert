#version 330 core
// A stack drawn at a level of detail as one tube (disk_lod.h, tube_mesh()): vertices in space-time,
// shaded with disk.frag like the instanced cylinders of disk.vert.
// Space-time (x, y, t) maps to GL (x, t * time_scale, -y): time is up, the ground is x-z.
layout(location = 0) in vec3 a_pos;  // world x, world y, global time
layout(location = 1) in vec4 a_dir;  // radial direction x, y; side slope m (metres per second); cap: +-1
uniform mat4 u_mvp;
uniform float u_time_scale;          // metres per second
uniform float u_clip_lo, u_clip_hi;  // GL heights kept: the time window (renderer.cpp)
uniform vec4 u_color;
out float gl_ClipDistance[2];
out vec3 v_normal;
out vec4 v_color;
void main() {
    v_color = u_color;
    vec3 p = vec3(a_pos.x, a_pos.z * u_time_scale, -a_pos.y);
    v_normal = a_dir.w != 0.0 ? vec3(0.0, a_dir.w, 0.0) : vec3(a_dir.x, -a_dir.z / u_time_scale, -a_dir.y);
    gl_Position = u_mvp * vec4(p, 1.0);
    gl_ClipDistance[0] = p.y - u_clip_lo;
    gl_ClipDistance[1] = u_clip_hi - p.y;
}
