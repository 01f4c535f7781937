#version 330 core
// One short cylinder per path sample, instanced: the unit cylinder (radius 1, height 0..1 along y)
// is scaled to the sample's radius r and duration dt and placed at its space-time position.
// Space-time (x, y, t) maps to GL (x, t * time_scale, -y): time is up, the ground is x-z.
// At a level of detail k > 1 an instance stands for a group of samples (disk_lod.h): a_group gives
// its height in samples and the shift of its top centre, and the cylinder is sheared along it.
// Ungrouped stacks leave location 3 unbound, which reads (0, 0, 0, 1): one sample, no shear.
// With u_mapped the colour is a_value on the colour map u_map (colour_map.h), else u_color.
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_sample;   // world x, world y, global start time t, radius r
layout(location = 3) in vec4 a_group;    // world dx, dy of the top centre, unused, samples in the group
layout(location = 4) in float a_value;   // the sample's (or group's) value of the disk colouring
uniform mat4 u_mvp;
uniform float u_time_scale;               // metres per second
uniform float u_dt;                       // seconds per sample
uniform float u_grow;                     // radius factor (highlighted disks are drawn a little larger)
uniform float u_clip_lo, u_clip_hi;       // GL heights kept: the time window (renderer.cpp)
uniform vec4 u_color;
uniform int u_mapped;
uniform int u_hide_caps;                  // 1: top caps inside the next group (a_group.z) are collapsed
uniform vec3 u_map[33];                   // the colour map, evenly spaced from u_lo to u_hi (either order)
uniform float u_lo, u_hi;
out float gl_ClipDistance[2];
out vec3 v_normal;
out vec4 v_color;
vec3 mapped(float v) {
    float x = (u_hi != u_lo ? clamp((v - u_lo) / (u_hi - u_lo), 0.0, 1.0) : 0.5) * 32.0;
    int i = min(int(x), 31);
    return mix(u_map[i], u_map[i + 1], x - float(i));
}
void main() {
    v_color = u_mapped != 0 ? vec4(mapped(a_value), u_color.a) : u_color;
    float r = a_sample.w * u_grow;
    float h = u_dt * a_group.w * u_time_scale;
    vec2 shift = a_group.xy * a_pos.y;
    // A cap inside the solid (the next group's base disk holds it) is never seen from outside: its
    // vertices go to its centre, and llvmpipe drops the empty triangles before rasterising them.
    float rim = (u_hide_caps != 0 && a_group.z > 0.5 && a_normal.y > 0.5) ? 0.0 : r;
    vec3 p = vec3(a_sample.x + shift.x + rim * a_pos.x, a_sample.z * u_time_scale + h * a_pos.y,
                  -(a_sample.y + shift.y) + rim * a_pos.z);
    // The side's normal tilts against the shear (GL shift is (dx, 0, -dy)); caps stay level.
    float tilt = (a_normal.x * a_group.x - a_normal.z * a_group.y) / max(abs(h), 1e-6);
    v_normal = vec3(a_normal.x, a_normal.y - tilt, a_normal.z);
    gl_Position = u_mvp * vec4(p, 1.0);
    gl_ClipDistance[0] = p.y - u_clip_lo;
    gl_ClipDistance[1] = u_clip_hi - p.y;
}
