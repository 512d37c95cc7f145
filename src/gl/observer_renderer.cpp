#include "gl/observer_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <glm/matrix.hpp>

#include "embedded_shaders.h"

namespace raycam::gl {

namespace {
const glm::vec3 kLightDirection = glm::normalize(glm::vec3(0.4f, 0.3f, 0.85f));

// A vertex array of interleaved vertices: a 3D position (attribute 0), then `second` floats (attribute 1).
void interleaved_vertices(GLuint& vao, GLuint& vbo, int second) {
  const GLsizei stride = GLsizei((3 + second) * sizeof(float));
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, second, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(3 * sizeof(float)));
}
}  // namespace

ObserverRenderer::ObserverRenderer()
    : sphere_program_(shaders::k_sphere_vert, shaders::k_sphere_frag, "sphere"),
      line_program_(shaders::k_lines_vert, shaders::k_lines_frag, "lines"),
      quad_program_(shaders::k_image_quad_vert, shaders::k_image_quad_frag, "image_quad"),
      layer_program_(shaders::k_sphere_layer_vert, shaders::k_sphere_layer_frag, "sphere_layer") {
  glGenVertexArrays(1, &sphere_vao_);
  glBindVertexArray(sphere_vao_);
  // Every sphere is one quad (a triangle strip), sized and turned towards the eye by sphere.vert.
  const float corners[] = {-1, -1, 1, -1, -1, 1, 1, 1};
  glGenBuffers(1, &sphere_corner_vbo_);
  glBindBuffer(GL_ARRAY_BUFFER, sphere_corner_vbo_);
  glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
  // Per-instance: centre + radius (vec4), colour (vec3).
  glGenBuffers(1, &sphere_instance_vbo_);
  glBindBuffer(GL_ARRAY_BUFFER, sphere_instance_vbo_);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 7 * sizeof(float), nullptr);
  glVertexAttribDivisor(1, 1);
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, 7 * sizeof(float), reinterpret_cast<void*>(4 * sizeof(float)));
  glVertexAttribDivisor(2, 1);

  interleaved_vertices(line_vao_, line_vbo_, 4);  // position + RGBA
  interleaved_vertices(quad_vao_, quad_vbo_, 2);  // position + texture coordinates
  glBindVertexArray(0);
}

ObserverRenderer::~ObserverRenderer() {
  const GLuint buffers[] = {sphere_corner_vbo_, sphere_instance_vbo_, line_vbo_, quad_vbo_};
  glDeleteBuffers(4, buffers);
  const GLuint arrays[] = {sphere_vao_, line_vao_, quad_vao_};
  glDeleteVertexArrays(3, arrays);
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
  if (colour_texture_) glDeleteTextures(1, &colour_texture_);
  if (depth_buffer_) glDeleteRenderbuffers(1, &depth_buffer_);
  const GLuint layers[] = {layer_colour_, layer_depth_};
  if (layer_colour_) glDeleteTextures(2, layers);
}

bool ObserverRenderer::uses_layer() const {
  return drawing_ == SphereDrawing::cpu_layer ||
         (drawing_ == SphereDrawing::automatic && std::size_t(sphere_count_) >= kSphereLayerFrom);
}

void ObserverRenderer::draw_sphere_layer(const ObserverFrame& frame, int width, int height) {
  SphereLayerView view;
  view.view_projection = glm::dmat4(frame.view_projection);
  view.eye = glm::dvec3(frame.observer_eye);
  view.light_direction = glm::dvec3(kLightDirection);
  view.width = width;
  view.height = height;
  if (layer_stale_ || !(view == layer_drawn_) || !layer_colour_) upload_sphere_layer(view);
  layer_program_.use();
  layer_program_.set("layer_colour", 0);
  layer_program_.set("layer_depth", 1);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, layer_colour_);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, layer_depth_);
  glBindVertexArray(quad_vao_);  // any vertex array: the triangle comes from gl_VertexID
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glActiveTexture(GL_TEXTURE0);
}

// Casts the layer (~20 ms of CPU at 10⁵ spheres) and uploads it: only when what it shows changed.
void ObserverRenderer::upload_sphere_layer(const SphereLayerView& view) {
  cast_sphere_layer(spheres_, view, layer_);
  ++layer_casts_;
  layer_drawn_ = view;
  layer_stale_ = false;
  const int width = view.width, height = view.height;
  if (!layer_colour_) {
    GLuint textures[2];
    glGenTextures(2, textures);
    layer_colour_ = textures[0];
    layer_depth_ = textures[1];
    for (const GLuint texture : textures) {
      glBindTexture(GL_TEXTURE_2D, texture);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, layer_colour_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, layer_.rgba.data());
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, layer_depth_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, width, height, 0, GL_RED, GL_FLOAT, layer_.depth.data());
}

void ObserverRenderer::set_spheres(const std::vector<Sphere>& spheres) {
  const std::size_t count = spheres.size();
  spheres_ = spheres;
  layer_stale_ = true;
  std::vector<float> instances;
  instances.reserve(count * 7);
  for (std::size_t i = 0; i < count; ++i) {
    const Sphere& s = spheres[i];
    instances.insert(instances.end(), {float(s.centre.x), float(s.centre.y), float(s.centre.z), float(s.radius),
                                       s.colour.r / 255.0f, s.colour.g / 255.0f, s.colour.b / 255.0f});
  }
  glBindBuffer(GL_ARRAY_BUFFER, sphere_instance_vbo_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(instances.size() * sizeof(float)), instances.data(), GL_STATIC_DRAW);
  sphere_count_ = GLsizei(count);
}

void ObserverRenderer::resize_target(int width, int height) {
  if (width == width_ && height == height_ && framebuffer_) return;
  if (!framebuffer_) {
    glGenFramebuffers(1, &framebuffer_);
    glGenTextures(1, &colour_texture_);
    glGenRenderbuffers(1, &depth_buffer_);
  }
  glBindTexture(GL_TEXTURE_2D, colour_texture_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_buffer_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_texture_, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_buffer_);
  width_ = width;
  height_ = height;
}

GLuint ObserverRenderer::render(const ObserverFrame& frame, int width, int height) {
  width = std::max(width, 1);
  height = std::max(height, 1);
  resize_target(width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width, height);
  glClearColor(frame.background.r / 255.0f, frame.background.g / 255.0f, frame.background.b / 255.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);

  if (uses_layer()) {
    draw_sphere_layer(frame, width, height);
  } else {
    sphere_program_.use();
    sphere_program_.set("view_projection", frame.view_projection);
    sphere_program_.set("clip_to_world", glm::inverse(frame.view_projection));
    sphere_program_.set("observer_eye", frame.observer_eye);
    sphere_program_.set("light_direction", kLightDirection);
    glBindVertexArray(sphere_vao_);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, sphere_count_);
  }

  if (frame.image_texture) {
    // Image order corners → uv with (0,0) at the top-left texel row 0.
    const auto& c = frame.screen_corners;
    const float quad[] = {c[0].x, c[0].y, c[0].z, 0, 0, c[1].x, c[1].y, c[1].z, 1, 0, c[2].x, c[2].y, c[2].z, 1, 1,
                          c[0].x, c[0].y, c[0].z, 0, 0, c[2].x, c[2].y, c[2].z, 1, 1, c[3].x, c[3].y, c[3].z, 0, 1};
    quad_program_.use();
    quad_program_.set("view_projection", frame.view_projection);
    quad_program_.set("colour_map", 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, frame.image_texture);
    glBindVertexArray(quad_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, quad_vbo_);
    glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, 6);
  }

  auto draw_lines = [&](const std::vector<ObserverLine>& lines) {
    if (lines.empty()) return;
    std::vector<float> vertices;
    vertices.reserve(lines.size() * 14);
    for (const ObserverLine& line : lines) {
      for (const glm::vec3& p : {line.from, line.to})
        vertices.insert(vertices.end(), {p.x, p.y, p.z, line.colour.r, line.colour.g, line.colour.b, line.colour.a});
    }
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    line_program_.use();
    line_program_.set("view_projection", frame.view_projection);
    glBindVertexArray(line_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, line_vbo_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(float)), vertices.data(), GL_STREAM_DRAW);
    glDrawArrays(GL_LINES, 0, GLsizei(lines.size() * 2));
  };
  draw_lines(frame.lines);
  glDisable(GL_DEPTH_TEST);  // the overlay shows through the spheres
  draw_lines(frame.overlay_lines);

  glBindVertexArray(0);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return colour_texture_;
}

}  // namespace raycam::gl
