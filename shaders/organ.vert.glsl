#version 330 core
// Organ surfaces: positions and normals are already in world space (the simulation moves
// the vertices themselves), so only the camera's view-projection applies.

layout(location = 0) in vec3 a_position;  // world space, metres
layout(location = 1) in vec3 a_normal;    // world space, unit length
layout(location = 2) in vec3 a_color;     // sRGB in [0, 1] (region or material colour)

// Variants, defined by the renderer: CLIP (a cutting plane), and WITH_OPACITY for the passes
// that split a surface by opacity (OPAQUE_PART, TRANSPARENT_PART). The plain variant is the
// opaque organ as before, so its pixels do not change.
#ifdef WITH_OPACITY
layout(location = 3) in float a_opacity;  // unit: 1, in [0, 1]
out float v_opacity;
#endif
#ifdef CLIP
uniform vec4 u_clip_plane;  // (normal, -dot(normal, point)): kept where >= 0, world space
#endif

uniform mat4 u_view_projection;

out vec3 v_position;  // world space
out vec3 v_normal;    // world space, interpolated (renormalised per fragment)
out vec3 v_albedo;    // linear RGB

// The exact sRGB transfer function (IEC 61966-2-1), decoded per vertex: the colour is
// constant over a region, so interpolating the linear value is what shading needs.
vec3 srgb_to_linear(vec3 c) {
  vec3 lo = c / 12.92;
  vec3 hi = pow((c + 0.055) / 1.055, vec3(2.4));
  return mix(hi, lo, vec3(lessThanEqual(c, vec3(0.04045))));
}

void main() {
  v_position = a_position;
  v_normal = a_normal;
  v_albedo = srgb_to_linear(clamp(a_color, 0.0, 1.0));
  gl_Position = u_view_projection * vec4(a_position, 1.0);
#ifdef WITH_OPACITY
  v_opacity = a_opacity;
#endif
#ifdef CLIP
  gl_ClipDistance[0] = dot(u_clip_plane.xyz, a_position) + u_clip_plane.w;
#endif
}
