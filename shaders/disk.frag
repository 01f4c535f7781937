#version 330 core
// Two-sided Lambert with a fixed light from above and behind the viewer: enough to read the stack.
in vec3 v_normal;
in vec4 v_color;
out vec4 o_color;
void main() {
    vec3 n = normalize(v_normal);
    vec3 l = normalize(vec3(0.35, 0.8, 0.5));
    float d = 0.45 + 0.55 * abs(dot(n, l));
    o_color = vec4(v_color.rgb * d, v_color.a);
}
