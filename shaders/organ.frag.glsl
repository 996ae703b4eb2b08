#version 330 core
// Wet living tissue for teaching videos, shaded in linear light:
//  - wrap-around diffuse: light bleeds past the terminator as it does through
//    translucent tissue, tinted by the tissue's own hue (red scatters further in flesh);
//  - Blinn-Phong highlight with the material's strength and exponent (the tissue's sheen),
//    plus a tight lobe with an 8 times higher exponent: the glint of the moist surface film;
//  - hemisphere ambient (sky above, warm bounce below, "up" = the camera's up);
//  - a subtle rim light that keeps the silhouette readable against a dark background.
// Output is encoded to sRGB here, so the framebuffer is plain 8-bit sRGB.

// LIGHT_COUNT (0..8, render::kMaxLights) is defined by the renderer, which compiles one
// program per count: a constant loop bound unrolls, a uniform one costs llvmpipe 2.4x the draw.
const int kLightCount = LIGHT_COUNT;
const int kLightArraySize = kLightCount > 0 ? kLightCount : 1;  // GLSL has no empty arrays.
const float kWrap = 0.3;         // how far light wraps past the terminator, unit: 1 (of N.L)
const float kRim = 0.07;         // rim light strength, unit: 1
const float kInsideShade = 0.6;  // an open surface's inner side, lit but in its own shadow, unit: 1
const float kWetShare = 0.6;     // the glint's share of the material's specular, unit: 1

in vec3 v_position;
in vec3 v_normal;
in vec3 v_albedo;

uniform vec3 u_camera_position;               // world space, metres
uniform vec3 u_light_to_light[kLightArraySize];  // unit vector from the surface towards the light
uniform vec3 u_light_radiance[kLightArraySize];  // linear RGB x intensity
uniform vec3 u_up;                            // unit: the hemisphere's "sky" direction
uniform vec3 u_sky;                           // linear RGB ambient from above
uniform vec3 u_ground;                        // linear RGB ambient from below
uniform float u_specular;                     // highlight strength, unit: 1
uniform float u_shininess;                    // Blinn-Phong exponent, unit: 1

#ifdef WITH_OPACITY
in float v_opacity;
// A fragment belongs to the opaque pass from this opacity up, to the transparent one below.
const float kOpaqueFrom = 0.999;
#endif
#ifdef CLIP
uniform vec3 u_cut_color;  // sRGB: the inside seen through the cut
const float kCutShade = 0.45;  // how much the inside darkens where it turns from the eye, unit: 1
#endif

#ifdef TRANSPARENT_PART
// Weighted blended order-independent transparency (McGuire & Bavoil, JCGT 2(2), 2013):
// every transparent fragment adds its premultiplied colour times a depth weight into
// accumulation, and multiplies revealage by (1 - alpha); a composite pass divides.
layout(location = 0) out vec4 accumulation;
layout(location = 1) out float revealage;
#else
out vec4 frag_color;
#endif

// Writes the sRGB colour: plainly in the opaque passes, weighted in the transparent one.
void emit(vec3 srgb) {
#ifdef TRANSPARENT_PART
  float a = v_opacity;
  // The paper's equation (9)-style weight on window depth: nearer layers count more.
  float w = clamp(pow(min(1.0, a * 10.0) + 0.01, 3.0) * 1e8 * pow(1.0 - gl_FragCoord.z * 0.9, 3.0), 1e-2, 3e3);
  accumulation = vec4(srgb * a, a) * w;
  revealage = a;
#else
  frag_color = vec4(srgb, 1.0);
#endif
}

// The sRGB transfer function (IEC 61966-2-1). Its power segment, c^(1/2.4), is a quintic in
// u = c^(1/4) (two square roots; a least-squares Chebyshev fit of u^(5/3) on the segment)
// instead of pow: llvmpipe's pow is a log2 and an exp2 polynomial each, and three a fragment
// cost the heart clip 0.27 s of its 5.9 s of CPU without the encoder (docs/performance.md).
// The fit is within 0.005 of an 8-bit step of the exact curve, so only a framebuffer value
// on a rounding boundary (one in a thousand) comes out a step apart (tests/render/srgb_test.cpp).
vec3 linear_to_srgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  vec3 lo = c * 12.92;
  vec3 u = sqrt(sqrt(c));
  vec3 power = -0.00635075 + u * (0.15672447 + u * (1.17911066 + u * (-0.52977373 + u * (0.26089498 + u * -0.06061611))));
  vec3 hi = 1.055 * power - 0.055;
  return mix(hi, lo, vec3(lessThanEqual(c, vec3(0.0031308))));
}

void main() {
#ifdef OPAQUE_PART
  if (v_opacity < kOpaqueFrom) discard;
#endif
#ifdef TRANSPARENT_PART
  if (v_opacity >= kOpaqueFrom) discard;
#endif
#ifdef CLIP
  // Back faces show only where the plane opened the surface: the inside, in the cut colour,
  // shaded by a headlight (full colour where the wall faces the eye) so cavities read in depth.
  if (!gl_FrontFacing) {
    float facing = max(dot(-normalize(v_normal), normalize(u_camera_position - v_position)), 0.0);
    emit(u_cut_color * (1.0 - kCutShade + kCutShade * facing));
    return;
  }
#endif
  // A back face reaches here only on a two-sided (open) surface: it is lit as the side the
  // eye sees. Closed surfaces cull back faces, so for them this is the plain normal.
  vec3 n = normalize(gl_FrontFacing ? v_normal : -v_normal);
  vec3 v = normalize(u_camera_position - v_position);
  vec3 albedo = v_albedo;
  // The tissue's hue at full strength: a saturated red scatters red, a pale region scatters white.
  vec3 hue = albedo / max(max(albedo.r, max(albedo.g, albedo.b)), 1e-4);

  float hemi = 0.5 + 0.5 * dot(n, u_up);
  vec3 color = albedo * mix(u_ground, u_sky, hemi);

  for (int i = 0; i < kLightCount; ++i) {
    vec3 l = u_light_to_light[i];
    float n_dot_l = dot(n, l);
    float lambert = max(n_dot_l, 0.0);
    float wrapped = max((n_dot_l + kWrap) / (1.0 + kWrap), 0.0);
    vec3 diffuse = albedo * (lambert + (wrapped - lambert) * hue);
    vec3 h = normalize(l + v);
    float n_dot_h = max(dot(n, h), 0.0);
    float sheen = pow(n_dot_h, u_shininess);
    float sheen2 = sheen * sheen;
    float sheen4 = sheen2 * sheen2;
    float glint = sheen4 * sheen4;  // pow(n_dot_h, 8 * shininess) without a second pow.
    float spec = u_specular * mix(sheen, 2.0 * glint, kWetShare) * smoothstep(0.0, 0.15, n_dot_l);
    color += u_light_radiance[i] * (diffuse + vec3(spec));
  }

  float grazing = 1.0 - max(dot(n, v), 0.0);
  float grazing2 = grazing * grazing;
  float rim = grazing2 * grazing2;
  color += kRim * rim * mix(u_sky, vec3(1.0), 0.5) * (0.5 + 0.5 * hue);

  if (!gl_FrontFacing) color *= kInsideShade;
  emit(linear_to_srgb(color));
}
