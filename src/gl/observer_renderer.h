// The observer's 3D view: the scene's spheres (ray-cast impostors, one instanced draw call, lightly shaded),
// coloured lines (the camera's frustum, screen, rays, axes) and the camera's colour map on its screen square,
// rasterised into an offscreen texture that the UI shows as an image. World: z up, as everywhere in raycam.
#pragma once

#include <array>
#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "gl/gl.h"
#include "raycam/scene.h"
#include "gl/shader_program.h"
#include "gl/sphere_layer.h"

namespace raycam::gl {

struct ObserverLine {
  glm::vec3 from{0.0f}, to{0.0f};
  glm::vec4 colour{1.0f};
};

struct ObserverFrame {
  glm::mat4 view_projection{1.0f};
  glm::vec3 observer_eye{0.0f};  // where view_projection looks from (the impostors cast rays from it)
  Rgb8 background{};
  std::vector<ObserverLine> lines;
  // Drawn over everything, with no depth test: the construction's intermediate camera, which sits inside the
  // objects around the origin until T(OP) moves it.
  std::vector<ObserverLine> overlay_lines;
  // The camera's screen, corners in image order (top-left, top-right, bottom-right, bottom-left), and the
  // texture to show on it (0: none).
  std::array<glm::vec3, 4> screen_corners{};
  GLuint image_texture = 0;
};

// How the spheres are drawn: GL impostors (one instanced draw call), or cast on the CPU into a layer that
// one full-screen triangle draws with its depth (gl/sphere_layer.h). Same picture; automatic picks the
// layer from kSphereLayerFrom spheres on, where llvmpipe's cost per primitive dominates.
enum class SphereDrawing { automatic, impostors, cpu_layer };

class ObserverRenderer {
 public:
  // Measured with `raycam-cli shot --soak` at 1280×720 (docs/speed.md).
  static constexpr std::size_t kSphereLayerFrom = 20000;

  ObserverRenderer();
  ~ObserverRenderer();
  ObserverRenderer(const ObserverRenderer&) = delete;
  ObserverRenderer& operator=(const ObserverRenderer&) = delete;

  // Uploads the spheres' instance data (and keeps a copy for the CPU layer); call only when the scene
  // changed.
  void set_spheres(const std::vector<Sphere>& spheres);
  void set_sphere_drawing(SphereDrawing drawing) { drawing_ = drawing; }
  // Draws into a width × height offscreen target and returns its colour texture (rows bottom-up, as GL).
  GLuint render(const ObserverFrame& frame, int width, int height);
  // How many times the CPU layer was cast: only when the observer's view, the size or the spheres changed
  // (moving the camera, hovering a pixel or typing leaves it as it was).
  long long sphere_layer_casts() const { return layer_casts_; }

 private:
  void resize_target(int width, int height);

  bool uses_layer() const;
  void draw_sphere_layer(const ObserverFrame& frame, int width, int height);
  void upload_sphere_layer(const SphereLayerView& view);

  ShaderProgram sphere_program_, line_program_, quad_program_, layer_program_;
  SphereDrawing drawing_ = SphereDrawing::automatic;
  std::vector<Sphere> spheres_;  // for the CPU layer
  SphereLayer layer_;
  SphereLayerView layer_drawn_;  // the view the layer's textures hold
  bool layer_stale_ = true;      // the spheres changed since
  long long layer_casts_ = 0;
  GLuint layer_colour_ = 0, layer_depth_ = 0;
  GLuint sphere_vao_ = 0, sphere_corner_vbo_ = 0, sphere_instance_vbo_ = 0;
  GLsizei sphere_count_ = 0;
  GLuint line_vao_ = 0, line_vbo_ = 0;
  GLuint quad_vao_ = 0, quad_vbo_ = 0;
  GLuint framebuffer_ = 0, colour_texture_ = 0, depth_buffer_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace raycam::gl
