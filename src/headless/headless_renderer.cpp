#include "headless/headless_renderer.h"

#include <GL/osmesa.h>  // the only file that includes OSMesa
#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <cfloat>
#include <stdexcept>
#include <vector>

#include "gl/gl.h"
#include "ui/renderer_backend.h"

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
  for (int key = 0; key < ImGuiKey_COUNT; ++key) io.KeyMap[key] = key;  // our key indices are ImGui's own
  mouse_x_ = mouse_y_ = -FLT_MAX;                                       // no mouse: nothing hovered
  ui::start_renderer_backend();
  frame_ = std::make_unique<ui::FrameRenderer>();
}

HeadlessRenderer::~HeadlessRenderer() {
  frame_.reset();  // GL objects go while the context is current
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext(context_->imgui);
  OSMesaDestroyContext(context_->mesa);
}

ui::FramebufferSize HeadlessRenderer::begin(const session::AppState&, const ui::PanelState&) {
  ImGuiIO& io = ImGui::GetIO();
  io.DeltaTime = 1.0f / 60.0f;
  io.DisplaySize = ImVec2(float(width_), float(height_));
  io.MousePos = ImVec2(mouse_x_, mouse_y_);  // the input a test injected (none: nothing hovered)
  for (int button = 0; button < 3; ++button) io.MouseDown[button] = mouse_down_[button];
  io.MouseWheel = wheel_;
  wheel_ = 0.0f;
  for (bool& down : io.KeysDown) down = false;
  if (pressed_key_ >= 0) io.KeysDown[pressed_key_] = true;
  pressed_key_ = -1;
  ImGui_ImplOpenGL3_NewFrame();
  return {width_, height_};
}

void HeadlessRenderer::present() { glFinish(); }

void HeadlessRenderer::run_frame(session::AppState& state) {
  layout_ = ui::run_frame(*this, *frame_, state).layout;
}

gl::RgbaImage HeadlessRenderer::render_settled(session::AppState& state, int frames) {
  for (int i = 0; i < std::max(frames, 2); ++i) run_frame(state);
  return read_back();
}

void HeadlessRenderer::move_mouse(float x, float y) {
  mouse_x_ = x;
  mouse_y_ = y;
}
void HeadlessRenderer::set_mouse_button(int button, bool down) { mouse_down_[button] = down; }
void HeadlessRenderer::scroll(float wheel) { wheel_ += wheel; }
void HeadlessRenderer::press_key(int imgui_key) { pressed_key_ = imgui_key; }
void HeadlessRenderer::type_text(const char* utf8) { ImGui::GetIO().AddInputCharactersUTF8(utf8); }

gl::RgbaImage HeadlessRenderer::read_back() const {
  glFinish();
  return gl::read_framebuffer(width_, height_);
}

}  // namespace raycam::headless
