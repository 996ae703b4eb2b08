#pragma once
// The OpenGL objects behind render::Renderer: the OSMesa context, shader programs and their
// variants, framebuffers and the order-independent-transparency targets. Internal to
// render/ (only the renderer's files include it), split out so the renderer reads as its passes.

// Only libOSMesa is linked: it exports the GL 4.5 entry points itself. Linking libGL as
// well would bind every gl* symbol to it and silently do nothing (docs/architecture.md).
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>

#include <Eigen/Core>
#include <string>
#include <string_view>

namespace systole::render::gl {

/// Throws Error(kInternal) "render: <what>".
[[noreturn]] void fail(const std::string& what);
/// sRGB channel value to linear light, clamped to [0, 1]. unit: 1
double srgb_to_linear(double c);
/// Fails naming `where` if OpenGL recorded an error.
void check_gl(const char* where);
/// An OSMesa core-profile context (4.5, else 3.3).
OSMesaContext create_context();
/// Compiles shaders/<name> with `defines` ("#define X 1\n" lines) inserted after its
/// #version line, which must come first.
GLuint compile_shader(GLenum type, std::string_view name, std::string_view defines);
GLuint link_program(std::string_view vertex_name, std::string_view fragment_name, std::string_view defines);
/// The location of a uniform the program must have.
GLint uniform(GLuint program, const char* name);
/// The #define lines of an organ program for a light count and variant bits.
std::string variant_defines(int light_count, int variant);

// Attribute locations, as in shaders/organ.vert.glsl.
constexpr GLuint kPositionAttrib = 0;
constexpr GLuint kNormalAttrib = 1;
constexpr GLuint kColorAttrib = 2;
constexpr GLuint kOpacityAttrib = 3;

/// Organ program variants (shaders/organ.*.glsl), as bits.
constexpr int kClipVariant = 1;         ///< CLIP: a cutting plane, back faces in the cut colour.
constexpr int kOpaquePartVariant = 2;   ///< OPAQUE_PART: drops the fragments below kOpaqueFrom.
constexpr int kTransparentPartVariant = 4;  ///< TRANSPARENT_PART: the OIT accumulation pass.
constexpr int kVariantCount = 8;
/// As kOpaqueFrom in organ.frag.glsl: a surface part is opaque from this opacity up.
constexpr float kOpaqueFrom = 0.999f;

// Hemisphere ambient, linear RGB: a cool sky and a warm bounce from below (the body cavity).
const Eigen::Vector3f kSkyAmbient(0.09f, 0.10f, 0.11f);
const Eigen::Vector3f kGroundAmbient(0.035f, 0.022f, 0.02f);

/// The organ shader compiled for one light count. The count is a compile-time constant
/// because llvmpipe runs a loop with a uniform bound (and the uniform-array indexing in it)
/// far slower than an unrolled one: 2.4x the whole draw of a 720p heart (docs/performance.md).
struct OrganProgram {
  GLuint id = 0;
  struct {
    GLint view_projection, camera_position, light_to_light, light_radiance, up, specular, shininess;
    GLint clip_plane = -1, cut_color = -1;  ///< CLIP variants only.
  } loc{};

  void create(int light_count, int variant) {
    id = link_program("organ.vert.glsl", "organ.frag.glsl", variant_defines(light_count, variant));
    if (variant & kClipVariant) {
      loc.clip_plane = uniform(id, "u_clip_plane");
      loc.cut_color = uniform(id, "u_cut_color");
    }
    loc.view_projection = uniform(id, "u_view_projection");
    loc.camera_position = uniform(id, "u_camera_position");
    loc.up = uniform(id, "u_up");
    loc.specular = uniform(id, "u_specular");
    loc.shininess = uniform(id, "u_shininess");
    // Without lights these are compiled out (-1: glUniform then does nothing).
    loc.light_to_light = glGetUniformLocation(id, "u_light_to_light");
    loc.light_radiance = glGetUniformLocation(id, "u_light_radiance");
    glUseProgram(id);
    glUniform3fv(uniform(id, "u_sky"), 1, kSkyAmbient.data());
    glUniform3fv(uniform(id, "u_ground"), 1, kGroundAmbient.data());
  }
};

/// A framebuffer with a colour and a depth renderbuffer (depth only when `with_depth`).
struct Framebuffer {
  GLuint fbo = 0;
  GLuint color = 0;
  GLuint depth = 0;

  void create(int width, int height, int samples, bool with_depth) {
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glGenRenderbuffers(1, &color);
    glBindRenderbuffer(GL_RENDERBUFFER, color);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    if (with_depth) {
      glGenRenderbuffers(1, &depth);
      glBindRenderbuffer(GL_RENDERBUFFER, depth);
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    }
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      fail("framebuffer incomplete (status 0x" + std::to_string(status) + ") at " +
           std::to_string(width) + "x" + std::to_string(height) + ", " + std::to_string(samples) +
           " samples");
    }
  }

  void destroy() noexcept {
    if (depth) glDeleteRenderbuffers(1, &depth);
    if (color) glDeleteRenderbuffers(1, &color);
    if (fbo) glDeleteFramebuffers(1, &fbo);
    *this = Framebuffer{};
  }
};

/// The weighted blended OIT targets, made on the first frame with a transparent part:
/// accumulation RGBA16F and revealage R16F, sharing the opaque pass's depth buffer (tested,
/// not written). With MSAA they are multisampled renderbuffers resolved into the textures.
struct OitTargets {
  GLuint fbo = 0;               ///< Drawn into by the transparent pass.
  GLuint accumulation_rb = 0, revealage_rb = 0;  ///< MSAA only.
  GLuint texture_fbo = 0;       ///< MSAA only: the resolve destination.
  GLuint accumulation = 0, revealage = 0;        ///< Textures the composite reads.
  GLuint composite_program = 0;
  GLuint empty_vao = 0;         ///< The composite's full-screen triangle has no attributes.

  void create(int width, int height, int samples, GLuint depth_renderbuffer) {
    const auto texture = [&](GLuint& id, GLenum format) {
      glGenTextures(1, &id);
      glBindTexture(GL_TEXTURE_2D, id);
      glTexStorage2D(GL_TEXTURE_2D, 1, format, width, height);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    };
    texture(accumulation, GL_RGBA16F);
    texture(revealage, GL_R16F);
    const GLenum both[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    if (samples > 0) {
      const auto renderbuffer = [&](GLuint& id, GLenum format) {
        glGenRenderbuffers(1, &id);
        glBindRenderbuffer(GL_RENDERBUFFER, id);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
      };
      renderbuffer(accumulation_rb, GL_RGBA16F);
      renderbuffer(revealage_rb, GL_R16F);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, accumulation_rb);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, revealage_rb);
    } else {
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, accumulation, 0);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, revealage, 0);
    }
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_renderbuffer);
    glDrawBuffers(2, both);
    check_complete("OIT accumulation");
    if (samples > 0) {
      glGenFramebuffers(1, &texture_fbo);
      glBindFramebuffer(GL_FRAMEBUFFER, texture_fbo);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, accumulation, 0);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, revealage, 0);
      glDrawBuffers(2, both);
      check_complete("OIT resolve");
    }
    composite_program = link_program("oit_composite.vert.glsl", "oit_composite.frag.glsl", "");
    glUseProgram(composite_program);
    glUniform1i(uniform(composite_program, "u_accumulation"), 0);
    glUniform1i(uniform(composite_program, "u_revealage"), 1);
    glGenVertexArrays(1, &empty_vao);
  }

  static void check_complete(const char* what) {
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) fail(std::string(what) + " framebuffer incomplete (status 0x" + std::to_string(status) + ")");
  }

  void destroy() noexcept {
    if (empty_vao) glDeleteVertexArrays(1, &empty_vao);
    if (composite_program) glDeleteProgram(composite_program);
    const GLuint framebuffers[] = {fbo, texture_fbo};
    glDeleteFramebuffers(2, framebuffers);
    const GLuint renderbuffers[] = {accumulation_rb, revealage_rb};
    glDeleteRenderbuffers(2, renderbuffers);
    const GLuint textures[] = {accumulation, revealage};
    glDeleteTextures(2, textures);
    *this = OitTargets{};
  }
};

}  // namespace systole::render::gl
