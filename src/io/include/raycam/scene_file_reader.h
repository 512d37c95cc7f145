// A scene file's text read in steps of a time budget each, for a page that must keep drawing while it opens
// 10⁶ spheres (docs/web.md, "Big files"): the same scene as parse_scene_json's, or the same error.
//   SceneFileReader reader(text, "big.json");
//   while (reader.step(40.0)) draw_a_frame_showing(reader.objects_read(), reader.objects_found());
//   SceneFile file = reader.take();  // or parse_scene_json's exception
// How: the top level of the text is split by its brackets and strings alone (finding), then each object of
// "objects" is parsed and checked by itself (reading), by the code parse_scene_json uses. Anything the
// splitting does not expect (a syntax error, an escaped key, a repeated key, a field that fails…) hands the
// whole text to parse_scene_json in one step: its error, word for word, or its scene.
#pragma once

#include <cstddef>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "raycam/scene_file.h"

namespace raycam {

class SceneFileReader {
 public:
  enum class Phase { finding, reading, done };

  SceneFileReader(std::string text, std::string source);

  // Works for about budget_ms (at least one object: 0 reads one object per step); false once done.
  bool step(double budget_ms);

  Phase phase() const { return phase_; }
  std::size_t bytes() const { return text_.size(); }
  std::size_t bytes_scanned() const { return at_; }  // while finding the objects
  std::size_t objects_found() const { return objects_.size(); }
  std::size_t objects_read() const { return next_object_; }

  // Once done: whether take() throws, and how many objects the scene it returns holds.
  bool failed() const { return error_ != nullptr; }
  std::size_t objects() const { return file_.scene2d.circles.size() + file_.scene3d.spheres.size(); }
  // Once done: the scene, or parse_scene_json's exception for this text.
  SceneFile take();

 private:
  bool find_members();  // the top level's fields, up to the objects' array or the end
  bool find_objects();  // the next few objects of the array (their byte ranges)
  bool read_fields();   // every field but the objects' contents, checked
  bool read_object();   // the next object, checked
  void fall_back();     // parse_scene_json on the whole text

  std::string text_, source_;
  Phase phase_ = Phase::finding;
  std::size_t at_ = 0;        // where finding goes on
  bool in_objects_ = false;   // at_ is inside the objects' array
  bool first_ = true;         // no member (or no object, in the array) found yet
  bool members_done_ = false;
  std::vector<std::pair<std::string, std::string>> members_;  // key as written (quoted), value's text
  std::vector<std::pair<std::size_t, std::size_t>> objects_;  // each object's [begin, end) in text_
  std::size_t next_object_ = 0;
  SceneFile file_;
  std::exception_ptr error_;
};

}  // namespace raycam
