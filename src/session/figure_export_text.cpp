// What Export figure says (figure_export.h): its own file, as the page's build has no figure drawing
// (src/web/figure_export_web.cpp) but shows the same panel.
#include <filesystem>

#include "session/figure_export.h"
#include "session/text.h"

namespace raycam::session {

namespace {
// The files of one export as one full path: "/home/x/figs/steps-a…f.svg" (their names differ only in the
// middle: the step's letter or number).
std::string file_range(const std::vector<std::string>& files) {
  const std::filesystem::path first(files.front()), last(files.back());
  const std::string a = first.filename().string(), b = last.filename().string();
  const auto inside_a_character = [](const std::string& text, std::size_t at) {
    return at < text.size() && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80;  // a UTF-8 continuation
  };
  std::size_t head = 0;
  while (head < a.size() && head < b.size() && a[head] == b[head]) ++head;
  while (head > 0 && (inside_a_character(a, head) || inside_a_character(b, head))) --head;
  std::size_t tail = 0;
  while (tail < a.size() - head && tail < b.size() - head && a[a.size() - 1 - tail] == b[b.size() - 1 - tail]) ++tail;
  while (tail > 0 && (inside_a_character(a, a.size() - tail) || inside_a_character(b, b.size() - tail))) --tail;
  const std::string range = a.substr(0, a.size() - tail) + "…" + b.substr(head, b.size() - head - tail) +
                            a.substr(a.size() - tail);
  return (first.parent_path() / range).string();
}
}  // namespace

std::string figure_files_message(Language language, const std::vector<std::string>& files) {
  if (files.empty()) return "";
  if (files.size() == 1) return trf(language, "wrote %s", files[0].c_str());
  return trf(language, "wrote %d {{file|files}}: %s", int(files.size()), file_range(files).c_str());
}

std::string figure_replace_question(Language language, const std::vector<std::string>& existing) {
  if (existing.size() == 1) return trf(language, "%s already exists. Replace it?", existing[0].c_str());
  return trf(language, "%d {{file already exists|files already exist}}: %s. Replace {{it|them}}?", int(existing.size()), file_range(existing).c_str());
}

}  // namespace raycam::session
