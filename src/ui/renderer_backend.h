// Dear ImGui's OpenGL 3 renderer backend, started and restarted in one place (the GLSL version is a fact of
// the platform: GL 3.3 core on the desktop and under OSMesa, WebGL 2 in the page).
#pragma once

namespace raycam::ui {

// ImGui_ImplOpenGL3_Init with the platform's GLSL version, after ImGui::CreateContext.
void start_renderer_backend();

// Shutdown and start again: the next NewFrame creates every device object afresh (the font texture from the
// current atlas included). Outside a frame, before the backend's NewFrame.
void restart_renderer_backend();

}  // namespace raycam::ui
