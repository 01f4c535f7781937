#version 330 core
// One short cylinder per path sample, instanced: the unit cylinder (radius 1, height 0..1 along y)
// is scaled to the sample's radius r and duration dt and placed at its space-time position.
// Space-time (x, y, t) maps to GL (x, t * time_scale, -y): time is up, the ground is x-z.
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_sample;   // world x, world y, global start time t, radius r
uniform mat4 u_mvp;
uniform float u_time_scale;               // metres per second
uniform float u_dt;                       // seconds per sample
uniform float u_grow;                     // radius factor (highlighted disks are drawn a little larger)
out vec3 v_normal;
void main() {
    float r = a_sample.w * u_grow;
    float h = u_dt * u_time_scale;
    vec3 p = vec3(a_sample.x + r * a_pos.x, a_sample.z * u_time_scale + h * a_pos.y, -a_sample.y + r * a_pos.z);
    v_normal = a_normal;
    gl_Position = u_mvp * vec4(p, 1.0);
}
