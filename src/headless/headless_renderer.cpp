#include "headless_renderer.h"

#include <cfloat>
#include <chrono>
#include <stdexcept>
#include <vector>

#include <GL/osmesa.h>  // the only file that includes OSMesa
#include <imgui.h>
#include <imgui_impl_opengl3.h>

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
  for (int key = 0; key < ImGuiKey_COUNT; ++key) io.KeyMap[key] = key;  // our key indices are ImGui's own
  mouse_x_ = mouse_y_ = -FLT_MAX;                                       // no mouse: nothing hovered
  ImGui_ImplOpenGL3_Init("#version 330 core");
  frame_ = std::make_unique<ui::FrameRenderer>();
}

HeadlessRenderer::~HeadlessRenderer() {
  frame_.reset();  // GL objects go while the context is current
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext(context_->imgui);
  OSMesaDestroyContext(context_->mesa);
}

void HeadlessRenderer::run_frame(ui::AppState& state) {
  const auto start = std::chrono::steady_clock::now();
  ImGuiIO& io = ImGui::GetIO();
  io.DeltaTime = 1.0f / 60.0f;
  io.MousePos = ImVec2(mouse_x_, mouse_y_);
  for (int button = 0; button < 3; ++button) io.MouseDown[button] = mouse_down_[button];
  io.MouseWheel = wheel_;
  wheel_ = 0.0f;
  for (bool& down : io.KeysDown) down = false;
  if (pressed_key_ >= 0) io.KeysDown[pressed_key_] = true;
  pressed_key_ = -1;
  raycam::ui::prepare_frame(state);          // fonts at the current scale, before the backend's frame
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
  layout_ = frame_->build(state, width_, height_);
  ImGui::Render();
  glViewport(0, 0, width_, height_);
  glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  glFinish();
  state.frame_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

gl::RgbaImage HeadlessRenderer::render_settled(ui::AppState& state, int frames) {
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

gl::RgbaImage HeadlessRenderer::read_back() const { return gl::read_framebuffer(width_, height_); }

}  // namespace raycam::headless
