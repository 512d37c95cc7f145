// The one place raycam includes OpenGL. Core-profile 3.3 prototypes, called directly: libGL (GLFW app) and
// libOSMesa (headless) both export every entry point, so no loader is needed. Neither library is linked
// here: each executable links the one that matches its context (both define the same GL symbols, so no
// binary links both).
#pragma once

#ifdef __EMSCRIPTEN__
#include <GLES3/gl3.h>  // the web build: WebGL 2 (src/web/)
#else
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES
#endif
#include <GL/glcorearb.h>
#endif
