#include "headless_renderer.h"

#include <GL/osmesa.h>  // the only file that includes OSMesa
#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <cfloat>
#include <stdexcept>
#include <vector>

#include "gl.h"

namespace raycam::headless {

struct HeadlessRenderer::Context {
  OSMesaContext mesa = nullptr;
  std::vector<unsigned char> buffer;
  ImGuiContext* imgui = nullptr;
};

HeadlessRenderer::HeadlessRenderer(int width, int height) : context_(std::make_unique<Context>()), width_(width), height_(height) {
  const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
  context_->mesa = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!context_->mesa) throw std::runtime_error("OSMesa: cannot create a GL 3.3 core context");
  context_->buffer.resize(std::size_t(width) * height * 4);
  if (!OSMesaMakeCurrent(context_->mesa, context_->buffer.data(), GL_UNSIGNED_BYTE, width, height))
    throw std::runtime_error("OSMesa: cannot make the context current");
  context_->imgui = ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini next to the user's files
  io.DisplaySize = ImVec2(float(width), float(height));
  ImGui_ImplOpenGL3_Init("#version 330 core");
  frame_ = std::make_unique<ui::FrameRenderer>();
}

HeadlessRenderer::~HeadlessRenderer() {
  frame_.reset();  // GL objects go while the context is current
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext(context_->imgui);
  OSMesaDestroyContext(context_->mesa);
}

ui::FramebufferSize HeadlessRenderer::begin(const ui::AppState&) {
  ImGuiIO& io = ImGui::GetIO();
  io.DeltaTime = 1.0f / 60.0f;
  io.DisplaySize = ImVec2(float(width_), float(height_));
  io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);  // no mouse: nothing hovered
  ImGui_ImplOpenGL3_NewFrame();
  return {width_, height_};
}

void HeadlessRenderer::present() { glFinish(); }

void HeadlessRenderer::run_frame(ui::AppState& state) {
  layout_ = ui::run_frame(*this, *frame_, state).layout;
}

gl::RgbaImage HeadlessRenderer::render_settled(ui::AppState& state, int frames) {
  for (int i = 0; i < std::max(frames, 2); ++i) run_frame(state);
  return read_back();
}

gl::RgbaImage HeadlessRenderer::read_back() const { return gl::read_framebuffer(width_, height_); }

}  // namespace raycam::headless
