#version 330 core
// Weighted blended OIT composite (McGuire & Bavoil 2013): the transparent layers' weighted
// mean colour over the opaque frame, covering 1 - revealage of it (blend: src alpha,
// 1 - src alpha). Pixels no transparent fragment touched are left alone.
uniform sampler2D u_accumulation;  // RGBA16F: sum of w * (alpha * sRGB, alpha)
uniform sampler2D u_revealage;     // R16F: product of (1 - alpha)

out vec4 frag_color;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float revealage = texelFetch(u_revealage, p, 0).r;
  if (revealage >= 1.0) discard;
  vec4 accumulation = texelFetch(u_accumulation, p, 0);
  vec3 mean = accumulation.rgb / clamp(accumulation.a, 1e-5, 5e4);
  frag_color = vec4(mean, 1.0 - revealage);
}
