#include "ui/image_header.h"

#include <imgui.h>

namespace raycam::ui {

namespace {
constexpr const char* kSeparator = "  |  ";
constexpr const char* kEllipsis = "…";

float width_of(const std::string& text) { return ImGui::CalcTextSize(text.c_str()).x; }

std::string joined(const std::vector<std::string>& parts, const char* separator = kSeparator) {
  std::string line;
  for (const std::string& part : parts)
    if (!part.empty()) line += (line.empty() ? "" : separator) + part;
  return line;
}
}  // namespace

float title_room(float width) {
  return width - 2 * ImGui::GetStyle().FramePadding.x - ImGui::GetStyle().WindowPadding.x;
}

std::string ellipsized(const std::string& text, float width) {
  if (width_of(text) <= width) return text;
  std::size_t end = text.size();
  while (end > 0) {
    do --end;  // back to the start of a UTF-8 character
    while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80);
    const std::string cut = text.substr(0, end) + kEllipsis;
    if (width_of(cut) <= width) return cut;
  }
  return kEllipsis;
}

ImageHeader fit_image_header(const ImageHeaderParts& parts, float width) {
  const float room = title_room(width);
  const std::vector<std::string> no_verdict = {""};
  const std::vector<std::string>& verdicts = parts.verdict.empty() ? no_verdict : parts.verdict;
  const std::vector<std::string> longest = {verdicts.front(), parts.mistake, parts.size.front()};
  auto header = [&](const std::string& title) {  // the tooltip: a line a part
    return ImageHeader{title, title == joined(longest) ? "" : joined(longest, "\n")};
  };
  // Whole parts first: the verdict's forms with the mistake and a size, then without the size.
  for (const std::string& size : parts.size)
    for (const std::string& verdict : verdicts)
      if (const std::string line = joined({verdict, parts.mistake, size}); width_of(line) <= room) return header(line);
  for (const std::string& verdict : verdicts)
    if (const std::string line = joined({verdict, parts.mistake}); width_of(line) <= room) return header(line);
  // The mistake cut after the longest verdict that leaves it room: cut with an ellipsis if that says more
  // than its brief form ("MISTAKE ON: pixel edges…"), else the brief form, else cut after its first word.
  const std::string& shortest = verdicts.back();
  if (!parts.mistake.empty()) {
    const float first_word = width_of(parts.mistake.substr(0, parts.mistake.find(' ')) + kEllipsis);
    for (const std::string& verdict : verdicts) {
      const std::string before = verdict.empty() ? "" : verdict + kSeparator;
      const float left = room - width_of(before);
      const std::string cut = ellipsized(parts.mistake, left);
      if (cut.size() > parts.mistake_brief.size() + std::string(kEllipsis).size() + 1) return header(before + cut);
      if (width_of(parts.mistake_brief) <= left) return header(before + parts.mistake_brief);
      if (left >= first_word) return header(before + cut);
    }
  }
  return header(shortest.empty() ? ellipsized(parts.size.back(), room) : shortest);
}

}  // namespace raycam::ui
