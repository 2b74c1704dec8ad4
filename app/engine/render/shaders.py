"""GLSL 3.30 sources of the offscreen renderer's three programs.

- ``SHADED``: lit, optionally textured triangles. Textures live in one per-asset atlas
  and are sampled with ``texelFetch`` and a manual, wrap-around bilinear filter, so
  glTF ``REPEAT`` uv outside [0, 1] works without one texture object per material.
  Lighting: ambient + a headlight (a point light riding with the camera, slightly above the eye), two-sided (``abs(n.l)``), since
  PartNet meshes have inconsistent winding. Vertex normals are used when given; a zero
  normal selects the flat triangle normal from screen-space derivatives.
- ``FLAT``: one uniform value per draw, written to a float target (ID buffer: link
  index + 1 and view depth; masks: 1.0).
- ``POINTS``: unlit, fixed-size point sprites in one uniform colour (overlay images).
"""

from __future__ import annotations

SHADED_VERTEX = """
#version 330
uniform mat4 u_view_projection;
uniform mat4 u_model;
in vec3 in_position;
in vec3 in_normal;
in vec2 in_uv;
in vec4 in_color;
in vec4 in_rect;
out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;
out vec4 v_color;
flat out vec4 v_rect;
void main() {
    vec4 world = u_model * vec4(in_position, 1.0);
    v_world = world.xyz;
    v_normal = mat3(u_model) * in_normal;
    v_uv = in_uv;
    v_color = in_color;
    v_rect = in_rect;
    gl_Position = u_view_projection * world;
}
"""

SHADED_FRAGMENT = """
#version 330
uniform sampler2D u_atlas;
uniform vec3 u_light;
uniform float u_ambient;
uniform float u_diffuse;
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_color;
flat in vec4 v_rect;
out vec4 f_color;

vec4 fetch_wrapped(ivec2 texel, ivec2 origin, ivec2 size) {
    ivec2 wrapped = ((texel % size) + size) % size;
    return texelFetch(u_atlas, origin + wrapped, 0);
}

vec4 sample_atlas(vec2 uv, vec4 rect) {
    ivec2 origin = ivec2(rect.xy);
    ivec2 size = max(ivec2(rect.zw), ivec2(1));
    vec2 position = fract(uv) * vec2(size) - 0.5;
    vec2 base = floor(position);
    vec2 weight = position - base;
    ivec2 t = ivec2(base);
    vec4 c00 = fetch_wrapped(t, origin, size);
    vec4 c10 = fetch_wrapped(t + ivec2(1, 0), origin, size);
    vec4 c01 = fetch_wrapped(t + ivec2(0, 1), origin, size);
    vec4 c11 = fetch_wrapped(t + ivec2(1, 1), origin, size);
    return mix(mix(c00, c10, weight.x), mix(c01, c11, weight.x), weight.y);
}

void main() {
    vec3 normal = v_normal;
    if (dot(normal, normal) < 0.25) {
        normal = cross(dFdx(v_world), dFdy(v_world));
    }
    float len = length(normal);
    normal = len > 0.0 ? normal / len : vec3(0.0, 0.0, 1.0);
    vec3 to_light = normalize(u_light - v_world);
    float lambert = abs(dot(normal, to_light));
    vec4 albedo = v_color;
    if (v_rect.z > 0.0) {
        albedo *= sample_atlas(v_uv, v_rect);
    }
    f_color = vec4(clamp(albedo.rgb * (u_ambient + u_diffuse * lambert), 0.0, 1.0), 1.0);
}
"""

FLAT_VERTEX = """
#version 330
uniform mat4 u_view_projection;
uniform mat4 u_model;
in vec3 in_position;
out float v_depth;
void main() {
    gl_Position = u_view_projection * u_model * vec4(in_position, 1.0);
    v_depth = gl_Position.w;
}
"""

FLAT_FRAGMENT = """
#version 330
uniform float u_value;
in float v_depth;
out vec2 f_value;
void main() {
    f_value = vec2(u_value, v_depth);
}
"""

POINTS_VERTEX = """
#version 330
uniform mat4 u_view_projection;
uniform mat4 u_model;
uniform float u_point_size;
in vec3 in_position;
void main() {
    gl_Position = u_view_projection * u_model * vec4(in_position, 1.0);
    gl_PointSize = u_point_size;
}
"""

POINTS_FRAGMENT = """
#version 330
uniform vec3 u_color;
out vec4 f_color;
void main() {
    f_color = vec4(u_color, 1.0);
}
"""
