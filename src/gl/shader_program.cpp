#include "gl/shader_program.h"

#include <stdexcept>
#include <utility>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

namespace raycam::gl {

namespace {
GLuint compile(GLenum stage, const char* source, const std::string& name) {
  const GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(std::size_t(length) + 1);
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    throw std::runtime_error("shader " + name + (stage == GL_VERTEX_SHADER ? " (vertex)" : " (fragment)") +
                             " does not compile: " + log.data());
  }
  return shader;
}
}  // namespace

ShaderProgram::ShaderProgram(const char* vertex_source, const char* fragment_source, const std::string& name) {
  const GLuint vertex = compile(GL_VERTEX_SHADER, vertex_source, name);
  const GLuint fragment = compile(GL_FRAGMENT_SHADER, fragment_source, name);
  program_ = glCreateProgram();
  glAttachShader(program_, vertex);
  glAttachShader(program_, fragment);
  glLinkProgram(program_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[1024] = {};
    glGetProgramInfoLog(program_, sizeof log, nullptr, log);
    glDeleteProgram(program_);
    program_ = 0;
    throw std::runtime_error("shader " + name + " does not link: " + log);
  }
}

ShaderProgram::~ShaderProgram() {
  if (program_) glDeleteProgram(program_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept : program_(std::exchange(other.program_, 0)) {}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
  std::swap(program_, other.program_);
  return *this;
}

void ShaderProgram::set(const char* uniform, const glm::mat4& value) const {
  glUniformMatrix4fv(glGetUniformLocation(program_, uniform), 1, GL_FALSE, glm::value_ptr(value));
}
void ShaderProgram::set(const char* uniform, const glm::vec3& value) const {
  glUniform3fv(glGetUniformLocation(program_, uniform), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* uniform, int value) const {
  glUniform1i(glGetUniformLocation(program_, uniform), value);
}

}  // namespace raycam::gl
