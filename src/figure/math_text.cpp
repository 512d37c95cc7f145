#include "figure/math_text.h"

#include <algorithm>
#include <cstring>

namespace raycam::figure {

namespace {

// The length of the UTF-8 character starting at text[i].
std::size_t char_length(const std::string& text, std::size_t i) {
  const unsigned char c = static_cast<unsigned char>(text[i]);
  const std::size_t n = c < 0x80 ? 1 : c < 0xe0 ? 2 : c < 0xf0 ? 3 : 4;
  return std::min(n, text.size() - i);
}

std::size_t char_count(const std::string& text) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < text.size(); i += char_length(text, i)) ++count;
  return count;
}

// The group after `_`, `^` or `\vec` at text[i]: `{…}` or one character. Moves i past it.
std::string group_at(const std::string& text, std::size_t& i) {
  if (i >= text.size()) return "";
  if (text[i] == '{') {
    const std::size_t close = text.find('}', i);
    const std::size_t end = close == std::string::npos ? text.size() : close;
    std::string group = text.substr(i + 1, end - i - 1);
    i = end == text.size() ? end : end + 1;
    return group;
  }
  const std::size_t n = char_length(text, i);
  std::string group = text.substr(i, n);
  i += n;
  return group;
}

// Symbols that LaTeX needs as commands (in mathematics).
struct Symbol {
  const char* utf8;
  const char* latex;
};
constexpr Symbol kMathSymbols[] = {
    {"θ", "\\theta "}, {"φ", "\\varphi "}, {"ψ", "\\psi "}, {"Ω", "\\Omega "}, {"α", "\\alpha "},
    {"π", "\\pi "},    {"‖", "\\| "},      {"−", "-"},      {"·", "\\cdot "}, {"°", "^{\\circ}"},
    {"²", "^{2}"},     {"…", "\\dots "},   {"×", "\\times "}, {"→", "\\to "}, {"∈", "\\in "},
    {" ", " "},  // a non-breaking space
};

std::string latex_math(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (text.compare(i, 3, "cos") == 0 || text.compare(i, 3, "sin") == 0) {  // upright operator names
      out += "\\" + text.substr(i, 3) + " ";
      i += 3;
      continue;
    }
    const std::size_t n = char_length(text, i);
    const std::string c = text.substr(i, n);
    bool done = false;
    for (const Symbol& s : kMathSymbols)
      if (c == s.utf8) {
        out += s.latex;
        done = true;
      }
    if (!done) {
      if (c == "," && i + 1 < text.size() && text[i + 1] >= '0' && text[i + 1] <= '9')
        out += "{,}";  // the decimal comma, not a separator followed by a space
      else if (c == "{" || c == "}" || c == "%" || c == "#" || c == "&" || c == "$" || c == "_")
        out += "\\" + c;
      else
        out += c;
    }
    i += n;
  }
  return out;
}

std::string latex_text(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = char_length(text, i);
    const std::string c = text.substr(i, n);
    i += n;
    if (c == "\\") {
      out += "\\textbackslash{}";
    } else if (c == "~" || c == "^") {
      out += "\\string" + c;
    } else if (std::strchr("{}%#&$_", c[0]) && n == 1) {
      out += "\\" + c;
    } else {
      bool symbol = false;
      for (const Symbol& s : kMathSymbols)
        if (c == s.utf8 && c != " ") {
          out += "\\ensuremath{" + std::string(s.latex) + "}";
          symbol = true;
        }
      if (!symbol) out += c;
    }
  }
  return out;
}

}  // namespace

std::vector<TextRun> parse_math_text(const std::string& markup) {
  std::vector<TextRun> runs;
  bool math = false;
  auto add = [&](const std::string& text, int level, bool vector) {
    if (text.empty()) return;
    if (!runs.empty() && runs.back().level == level && !runs.back().vector && !vector &&
        runs.back().math == math)
      runs.back().text += text;
    else
      runs.push_back({text, level, vector, math});
  };
  for (std::size_t i = 0; i < markup.size();) {
    const char c = markup[i];
    if (c == '\\' && i + 1 < markup.size() && (markup[i + 1] == '$' || markup[i + 1] == '\\')) {
      add(std::string(1, markup[i + 1]), 0, false);
      i += 2;
    } else if (c == '$') {
      math = !math;
      ++i;
    } else if (math && (c == '_' || c == '^')) {
      ++i;
      add(group_at(markup, i), c == '_' ? -1 : 1, false);
    } else if (math && markup.compare(i, 5, "\\vec{") == 0) {
      i += 4;
      add(group_at(markup, i), 0, true);
    } else {
      const std::size_t n = char_length(markup, i);
      add(markup.substr(i, n), 0, false);
      i += n;
    }
  }
  return runs;
}

std::string latex_of(const std::string& markup) {
  std::string out;
  bool math = false;
  for (const TextRun& run : parse_math_text(markup)) {
    if (run.math != math) {
      out += "$";
      math = run.math;
    }
    if (!run.math) {
      out += latex_text(run.text);
      continue;
    }
    const std::string body = latex_math(run.text);
    if (run.vector)  // \vec is sized for one letter; PC⃗ and ΩP⃗ need the long arrow
      out += (char_count(run.text) > 1 ? "\\overrightarrow{" : "\\vec{") + body + "}";
    else if (run.level < 0)
      out += "_{" + body + "}";
    else if (run.level > 0)
      out += "^{" + body + "}";
    else
      out += body;
  }
  if (math) out += "$";
  return out;
}

std::string plain_text_of(const std::string& markup) {
  std::string out;
  for (const TextRun& run : parse_math_text(markup)) out += run.text;
  return out;
}

std::string escape_markup(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '$' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace raycam::figure
