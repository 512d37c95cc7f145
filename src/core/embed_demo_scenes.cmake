# Writes OUTPUT, the C++ initialisers of the built-in demo scenes, from SCENE_2D and SCENE_3D (scenes/
# classic2d.json and classic3d.json). The files are the one definition of the demo scene: the app's
# default, the stress cases' cluster and the accuracy benchmark all start from them, and a student opening
# the file sees exactly the built-in scene. Read at build time, so the core itself reads no file.
function(scene_initialiser path kind out_background out_objects)
  file(READ ${path} json)
  string(JSON background GET "${json}" background)
  string(JSON r GET "${background}" 0)
  string(JSON g GET "${background}" 1)
  string(JSON b GET "${background}" 2)
  set(${out_background} "{${r}, ${g}, ${b}}" PARENT_SCOPE)
  string(JSON count LENGTH "${json}" objects)
  math(EXPR last "${count} - 1")
  set(objects "")
  foreach(i RANGE ${last})
    string(JSON type GET "${json}" objects ${i} type)
    if(NOT type STREQUAL kind)
      message(FATAL_ERROR "${path}: objects[${i}] is a ${type}, expected a ${kind}")
    endif()
    string(JSON centre GET "${json}" objects ${i} center)
    string(JSON centre_length LENGTH "${json}" objects ${i} center)
    math(EXPR centre_last "${centre_length} - 1")
    set(coordinates "")
    foreach(axis RANGE ${centre_last})
      string(JSON value GET "${centre}" ${axis})
      list(APPEND coordinates "${value}")
    endforeach()
    list(JOIN coordinates ", " coordinates)
    string(JSON radius GET "${json}" objects ${i} radius)
    string(JSON colour GET "${json}" objects ${i} color)
    string(JSON cr GET "${colour}" 0)
    string(JSON cg GET "${colour}" 1)
    string(JSON cb GET "${colour}" 2)
    string(JSON name GET "${json}" objects ${i} name)
    string(APPEND objects "      {{${coordinates}}, ${radius}, {${cr}, ${cg}, ${cb}}, \"${name}\"},\n")
  endforeach()
  set(${out_objects} "${objects}" PARENT_SCOPE)
endfunction()

set(body "// Generated from scenes/classic2d.json and scenes/classic3d.json by src/core/embed_demo_scenes.cmake.
// Do not edit: edit the scene files.
#pragma once
namespace raycam::generated {
")
foreach(dimension 2 3)
  if(dimension EQUAL 2)
    set(kind circle)
    set(list circles)
  else()
    set(kind sphere)
    set(list spheres)
  endif()
  scene_initialiser(${SCENE_${dimension}D} ${kind} background objects)
  string(APPEND body "inline Scene${dimension}D demo_scene_${dimension}d() {
  Scene${dimension}D scene;
  scene.background = Rgb8${background};
  scene.${list} = {
${objects}  };
  return scene;
}
")
endforeach()
string(APPEND body "}  // namespace raycam::generated\n")
file(WRITE ${OUTPUT} "${body}")
