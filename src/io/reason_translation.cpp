// translate_reason(): each ReasonPattern's English becomes an anchored regular expression once (literal text
// escaped, each placeholder a lazy group, each plural group "{{one|many}}" either form), matched against the
// whole reason; the asked language's template is then filled with the captured parts, each plural group
// taking the form the last number filled in before it asks for (takes_plural(), as format_text() does).
#include <regex>

#include "raycam/language.h"

namespace raycam {

namespace {
// A placeholder "{name}" or "{name*}" (submatches 1, 2), or a plural group "{{one|many}}" (submatches 3, 4).
const std::regex kPart(R"(\{([a-z_]+)(\*?)\}|\{\{([^{}|]*)\|([^{}|]*)\}\})");
bool is_plural_group(const std::smatch& part) { return part[3].matched; }

struct CompiledPattern {
  std::regex english;
  std::vector<std::string> names;  // in capture order
  std::vector<bool> nested;        // "{name*}": translated in turn
  const ReasonPattern* templates;  // every language's
};

std::string escaped(const std::string& literal) {
  static const std::string special = R"(\^$.|?*+()[]{})";
  std::string out;
  for (char c : literal) {
    if (special.find(c) != std::string::npos) out += '\\';
    out += c;
  }
  return out;
}

CompiledPattern compile(const ReasonPattern& pattern) {
  CompiledPattern compiled;
  const std::string en = pattern.english();
  std::string expression;
  std::size_t last = 0;
  for (auto it = std::sregex_iterator(en.begin(), en.end(), kPart); it != std::sregex_iterator(); ++it) {
    expression += escaped(en.substr(last, std::size_t(it->position()) - last));
    last = std::size_t(it->position() + it->length());
    if (is_plural_group(*it)) {  // the code writes the form its count asks for: either matches
      expression += "(?:" + escaped((*it)[3]) + "|" + escaped((*it)[4]) + ")";
      continue;
    }
    expression += "(.+?)";
    compiled.names.push_back((*it)[1]);
    compiled.nested.push_back((*it)[2].length() > 0);
  }
  expression += escaped(en.substr(last));
  compiled.english = std::regex(expression);
  compiled.templates = &pattern;
  return compiled;
}

const std::vector<CompiledPattern>& compiled_patterns() {
  static const std::vector<CompiledPattern> all = [] {
    std::vector<CompiledPattern> out;
    for (const ReasonPattern& pattern : reason_patterns()) out.push_back(compile(pattern));
    return out;
  }();
  return all;
}

// `text` read as a whole number ("2", "-1") into `count`; anything else ("[0, 255]", "a.json") leaves it.
void whole_number(const std::string& text, long long& count) {
  const std::size_t digits = text.find_first_not_of("0123456789", text.size() > 1 && text[0] == '-' ? 1 : 0);
  if (text.empty() || text == "-" || digits != std::string::npos || text.size() > 18) return;
  count = std::stoll(text);
}

// Nested reasons are a few levels deep at most (a detail around a reason around a phrase); the bound only
// guards against a table whose patterns would feed each other forever.
constexpr int kMaxDepth = 8;
// std::regex matches by recursion, about one level per character: a reason longer than this (a path pasted
// by mistake, tens of kilobytes) would overflow the stack, so it is shown as it is.
constexpr std::size_t kMaxLength = 2048;

std::string translated(Language language, const std::string& english, std::vector<std::size_t>* used, int depth) {
  if (depth > kMaxDepth || english.size() > kMaxLength) return english;
  const std::vector<CompiledPattern>& patterns = compiled_patterns();
  for (std::size_t i = 0; i < patterns.size(); ++i) {
    const CompiledPattern& p = patterns[i];
    std::smatch match;
    if (!std::regex_match(english, match, p.english)) continue;
    if (used) used->push_back(i);
    std::vector<std::string> parts;
    for (std::size_t k = 0; k < p.names.size(); ++k)
      parts.push_back(p.nested[k] ? translated(language, match[k + 1], used, depth + 1) : std::string(match[k + 1]));
    // One pass over the template: a captured part that looks like "{name}" is never filled in turn.
    const std::string form = (*p.templates)[language];
    std::string text;
    std::size_t last = 0;
    long long count = 0;  // the last part filled in that is a whole number: it picks the next group's form
    for (auto it = std::sregex_iterator(form.begin(), form.end(), kPart); it != std::sregex_iterator(); ++it) {
      text += form.substr(last, std::size_t(it->position()) - last);
      last = std::size_t(it->position() + it->length());
      if (is_plural_group(*it)) {
        text += takes_plural(language, count) ? (*it)[4].str() : (*it)[3].str();
        continue;
      }
      std::size_t k = 0;
      while (k < p.names.size() && p.names[k] != (*it)[1]) ++k;
      text += k < p.names.size() ? parts[k] : it->str();
      if (k < p.names.size()) whole_number(parts[k], count);
    }
    text += form.substr(last);
    return text;
  }
  return english;
}
}  // namespace

std::string translate_reason(Language language, const std::string& english, std::vector<std::size_t>* used) {
  if (language == Language::en) return english;
  return translated(language, english, used, 0);
}

}  // namespace raycam
