# Writes OUTPUT, a header with each shader in SHADERS as a string constant kShader_<name>_<stage>,
# so that the executables do not depend on finding shaders/ at run time. With GLSL_ES, each becomes its
# GLSL ES 3.00 form (the web build): only the version line changes and a default precision is added.
set(body "// Generated from shaders/ by src/gl/embed_shaders.cmake. Do not edit.\n#pragma once\nnamespace raycam::gl::shaders {\n")
string(REPLACE "|" ";" SHADERS "${SHADERS}")
foreach(shader ${SHADERS})
  get_filename_component(name ${shader} NAME_WE)
  get_filename_component(stage ${shader} EXT)
  string(SUBSTRING ${stage} 1 -1 stage)
  file(READ ${shader} source)
  if(GLSL_ES)  # WebGL 2: the same source as GLSL ES 3.00, which wants a default float precision
    string(REPLACE "#version 330 core\n" "#version 300 es\nprecision highp float;\nprecision highp int;\n" source "${source}")
  endif()
  string(APPEND body "inline constexpr const char* k_${name}_${stage} = R\"glsl(${source})glsl\";\n")
endforeach()
string(APPEND body "}  // namespace raycam::gl::shaders\n")
file(WRITE ${OUTPUT} "${body}")
