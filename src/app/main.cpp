// raycam: the interactive window (GLFW + Dear ImGui + OpenGL 3.3 core). The only file that includes GLFW;
// the frame itself is raycam_ui's, shared with the headless `raycam-cli shot`.
#include <cfloat>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "app_options.h"
#include "frame.h"
#include "framebuffer_image.h"
#include "gl.h"

namespace {
using raycam::ui::AppState;

struct Run {
  int frames = 0;          // 0: interactive; N: run N frames then exit
  std::string screenshot;  // with --frames: the last frame's PNG
};

void print_help() {
  std::printf(
      "usage: raycam [SCENE.json] [--scene FILE] [camera flags] [--width W --height H] [--inspect COL,ROW]\n"
      "              [--step K] [--mistake NAME] [--font-scale S] [--frames N --screenshot out.png]\n\n"
      "The interactive raycam window. With no scene, a built-in demo scene opens. F1 lists the shortcuts.\n\n%s%s"
      "  --frames N          run N frames (no user input) and exit; N in [1, 100000]\n"
      "  --screenshot FILE   with --frames: save the last frame as PNG (the same image as raycam-cli shot)\n",
      raycam::view_flags_help(), raycam::ui::app_options_help());
}

void key_callback(GLFWwindow* window, int key, int, int action, int) {
  if (action != GLFW_PRESS) return;
  auto* state = static_cast<AppState*>(glfwGetWindowUserPointer(window));
  if (key == GLFW_KEY_F1) state->show_help = !state->show_help;
  if (key == GLFW_KEY_F11) state->request_fullscreen = true;
  if (key == GLFW_KEY_F12) raycam::ui::request_screenshot(*state);
  if (key == GLFW_KEY_Q && (glfwGetKey(window, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS)) state->request_quit = true;
}

void drop_callback(GLFWwindow* window, int count, const char** paths) {
  // A bad file shows its error in the status line and keeps the current scene.
  if (count > 0) raycam::ui::open_scene(*static_cast<AppState*>(glfwGetWindowUserPointer(window)), paths[0]);
}

void toggle_fullscreen(GLFWwindow* window, int& saved_x, int& saved_y, int& saved_w, int& saved_h) {
  if (glfwGetWindowMonitor(window)) {
    glfwSetWindowMonitor(window, nullptr, saved_x, saved_y, saved_w, saved_h, 0);
    return;
  }
  GLFWmonitor* monitor = glfwGetPrimaryMonitor();
  if (!monitor) return;
  glfwGetWindowPos(window, &saved_x, &saved_y);
  glfwGetWindowSize(window, &saved_w, &saved_h);
  const GLFWvidmode* mode = glfwGetVideoMode(monitor);
  glfwSetWindowMonitor(window, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
}
}  // namespace

int main(int argc, char** argv) {
  raycam::ui::AppOptions options;
  options.demo_on_bad_scene = true;  // open on the demo scene and show why the file did not open
  Run run;
  AppState state;
  try {
    const std::vector<std::string> args(argv + 1, argv + argc);
    for (std::size_t i = 0; i < args.size();) {
      if (args[i] == "--help" || args[i] == "-h") {
        print_help();
        return 0;
      }
      if (raycam::ui::parse_app_option(args, i, options)) continue;
      if (args[i] == "--frames" || args[i] == "--screenshot") {
        if (i + 1 >= args.size()) throw std::invalid_argument(args[i] + ": missing value");
        if (args[i] == "--screenshot") {
          run.screenshot = args[i + 1];
        } else {
          run.frames = raycam::parse_integer_flag(args[i + 1], "--frames", 1, 100000);
        }
        i += 2;
      } else if (args[i].rfind("--", 0) != 0 && !options.view.scene_path) {
        options.view.scene_path = args[i++];  // `raycam SCENE.json`
      } else {
        throw std::invalid_argument("unknown option '" + args[i] + "' (see raycam --help)");
      }
    }
    if (!run.screenshot.empty() && run.frames == 0) run.frames = 3;
    state = raycam::ui::make_app_state(options);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "raycam: error: %s\n", error.what());
    return 2;
  }

  glfwSetErrorCallback([](int, const char* message) { std::fprintf(stderr, "raycam: GLFW: %s\n", message); });
  if (!glfwInit()) {
    std::fprintf(stderr, "raycam: cannot open a window (no display?). For a headless render use: raycam-cli shot\n");
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(options.width, options.height, "raycam", nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    std::fprintf(stderr, "raycam: cannot create a GL 3.3 core window\n");
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(run.frames > 0 ? 0 : 1);
  glfwSetWindowUserPointer(window, &state);
  glfwSetKeyCallback(window, key_callback);  // before ImGui's backend, which chains to it
  glfwSetDropCallback(window, drop_callback);

  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  int exit_code = 0;
  {
    raycam::ui::FrameRenderer frame;
    int saved[4] = {0, 0, options.width, options.height};
    std::string applied_title = "raycam";
    for (int frame_index = 0; !glfwWindowShouldClose(window) && !state.request_quit; ++frame_index) {
      const auto start = std::chrono::steady_clock::now();
      glfwPollEvents();
      int width = 0, height = 0;
      glfwGetFramebufferSize(window, &width, &height);
      if (width <= 0 || height <= 0) continue;  // minimised
      raycam::ui::prepare_frame(state);         // fonts at the current scale, before the backend's frame
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      if (run.frames > 0) ImGui::GetIO().MousePos = ImVec2(-FLT_MAX, -FLT_MAX);  // scripted: no stray hover
      ImGui::NewFrame();
      frame.build(state, width, height);
      if (state.window_title != applied_title) {  // the UI names the mode and the scene; the host applies it
        glfwSetWindowTitle(window, state.window_title.c_str());
        applied_title = state.window_title;
      }
      ImGui::Render();
      glViewport(0, 0, width, height);
      glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      const bool last = run.frames > 0 && frame_index + 1 >= run.frames;
      if (state.request_screenshot || (last && !run.screenshot.empty())) {
        const std::string path = last && !run.screenshot.empty() ? run.screenshot : state.screenshot_path;
        try {
          glFinish();
          raycam::gl::write_png(raycam::gl::read_framebuffer(width, height), path);  // back buffer, before the swap
          set_message(state, raycam::ui::MessageSource::files, false,
                      raycam::ui::trf("wrote %s", path.c_str()));
        } catch (const std::exception& error) {
          set_message(state, raycam::ui::MessageSource::files, true, error.what());
          if (last) exit_code = 1;
        }
        state.request_screenshot = false;
      }
      if (state.request_fullscreen) {
        toggle_fullscreen(window, saved[0], saved[1], saved[2], saved[3]);
        state.request_fullscreen = false;
      }
      glfwSwapBuffers(window);
      state.frame_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      if (last) break;
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  if (exit_code != 0) std::fprintf(stderr, "raycam: error: %s\n", state.message.c_str());
  return exit_code;
}
