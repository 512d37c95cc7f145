// format_text(): printf in a language's way. Each conversion is written by the C library on its own (the C
// locale: a point), then a floating one gets the language's decimal mark; a plural group "{{one|many}}"
// keeps the form the integer conversion before it asks for. One formatter for every table: the window's, the
// checker's, the figures'.
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>

#include "raycam/language.h"

namespace raycam {

namespace {

// va_list in a struct, so that it can be passed on by reference and consumed across calls.
struct Arguments {
  va_list list;
};

// The end of the conversion starting at text[at] == '%' (one past its letter).
std::size_t conversion_end(std::string_view text, std::size_t at) {
  std::size_t end = at + 1;
  while (end < text.size() && std::strchr("-+ #0123456789.*hlLqjzt", text[end])) ++end;
  return end < text.size() ? end + 1 : end;
}

// (The spec is a const char*: va_start on a reference parameter is undefined.)
std::string printed(const char* spec, ...) {
  va_list args;
  va_start(args, spec);
  va_list copy;
  va_copy(copy, args);
  const int size = std::vsnprintf(nullptr, 0, spec, copy);
  va_end(copy);
  std::string text(size > 0 ? std::size_t(size) : 0, '\0');
  if (size > 0) std::vsnprintf(text.data(), text.size() + 1, spec, args);
  va_end(args);
  return text;
}

// An integer conversion with its length made "ll": "%02d" → "%02lld", "%zu" → "%llu".
std::string as_long_long(const std::string& spec) {
  std::string bare = spec.substr(0, spec.size() - 1);
  while (!bare.empty() && std::strchr("hlLqjzt", bare.back())) bare.pop_back();
  return bare + "ll" + spec.back();
}

// One conversion `spec` ("%.2f", "%lld", "%s"...) with its argument taken from `args`; `count` receives an
// integer conversion's value.
std::string one_conversion(Language language, const std::string& asked, Arguments& args, long long* count) {
  // A '*' width or precision takes its int from the arguments, before the value, as printf does: written into
  // the conversion here ("%.*f" with 3 → "%.3f"). Read as the value, it was a double taken from an int's place
  // (a precision of millions: gigabytes of digits, some runs).
  std::string spec = asked;
  for (std::size_t star = spec.find('*'); star != std::string::npos; star = spec.find('*', star)) {
    const int number = va_arg(args.list, int);
    const bool precision = star > 0 && spec[star - 1] == '.';
    if (precision && number < 0) {  // a negative precision is no precision
      spec.erase(star - 1, 2);
      star -= 1;
      continue;
    }
    const std::string digits = std::to_string(number);
    spec.replace(star, 1, digits);
    star += digits.size();
  }
  const char letter = spec.back();
  const bool ll = spec.find("ll") != std::string::npos || spec.find('j') != std::string::npos;
  const bool l = !ll && spec.find('l') != std::string::npos;
  const bool z = spec.find('z') != std::string::npos || spec.find('t') != std::string::npos;
  switch (letter) {
    case 'd': case 'i': {
      const long long value = ll ? va_arg(args.list, long long) : l ? va_arg(args.list, long)
                              : z ? (long long)va_arg(args.list, std::ptrdiff_t) : va_arg(args.list, int);
      if (count) *count = value;
      return printed(as_long_long(spec).c_str(), value);
    }
    case 'u': case 'x': case 'X': case 'o': {
      const unsigned long long value = ll ? va_arg(args.list, unsigned long long)
                                       : l ? va_arg(args.list, unsigned long)
                                       : z ? (unsigned long long)va_arg(args.list, std::size_t)
                                           : va_arg(args.list, unsigned);
      if (count) *count = (long long)value;
      return printed(as_long_long(spec).c_str(), value);
    }
    case 'c': return printed(spec.c_str(), va_arg(args.list, int));
    case 's': return printed(spec.c_str(), va_arg(args.list, const char*));
    case 'p': return printed(spec.c_str(), va_arg(args.list, void*));
    case 'f': case 'F': case 'e': case 'E': case 'g': case 'G': case 'a': case 'A': {
      std::string text = spec.find('L') != std::string::npos ? printed(spec.c_str(), va_arg(args.list, long double))
                                                             : printed(spec.c_str(), va_arg(args.list, double));
      if (language == Language::fr)
        for (char& c : text)
          if (c == '.') c = ',';
      return text;
    }
    default: return spec;  // not a conversion this formatter knows: shown as it is
  }
}

}  // namespace

bool takes_plural(Language language, long long count) {
  switch (language) {
    case Language::fr: return count >= 2 || count <= -2;  // "0 pixel faux", "1,5 pixel"
    case Language::en: break;
  }
  return count != 1 && count != -1;  // "0 pixels wrong", "1 pixel wrong"
}

std::string format_text(Language language, const char* format, va_list list) {
  Arguments args;
  va_copy(args.list, list);
  const std::string_view text(format);
  std::string out;
  long long count = 0;  // the last integer conversion's value: it picks the next plural group's form
  for (std::size_t at = 0; at < text.size();) {
    if (text.compare(at, 2, "%%") == 0) {
      out += '%';
      at += 2;
    } else if (text[at] == '%') {
      const std::size_t end = conversion_end(text, at);
      out += one_conversion(language, std::string(text.substr(at, end - at)), args, &count);
      at = end;
    } else if (const std::size_t bar = text.find('|', at), end = text.find("}}", at);
               text.compare(at, 2, "{{") == 0 && bar < end && end != std::string_view::npos) {
      out += takes_plural(language, count) ? text.substr(bar + 1, end - bar - 1) : text.substr(at + 2, bar - at - 2);
      at = end + 2;
    } else {
      out += text[at++];
    }
  }
  va_end(args.list);
  return out;
}

std::string formatted(Language language, const char* format, ...) {
  va_list args;
  va_start(args, format);
  std::string text = format_text(language, format, args);
  va_end(args);
  return text;
}

}  // namespace raycam
