// A linked GLSL program built from two embedded sources; throws std::runtime_error with the GL log.
#pragma once

#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "gl/gl.h"

namespace raycam::gl {

class ShaderProgram {
 public:
  ShaderProgram() = default;
  ShaderProgram(const char* vertex_source, const char* fragment_source, const std::string& name);
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;
  ShaderProgram(ShaderProgram&& other) noexcept;
  ShaderProgram& operator=(ShaderProgram&& other) noexcept;

  void use() const { glUseProgram(program_); }
  void set(const char* uniform, const glm::mat4& value) const;
  void set(const char* uniform, const glm::vec3& value) const;
  void set(const char* uniform, int value) const;

 private:
  GLuint program_ = 0;
};

}  // namespace raycam::gl
