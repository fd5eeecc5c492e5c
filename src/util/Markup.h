#pragma once
// Text placed in SVG or HTML (element content or attribute values), escaped.
#include <string>

namespace mms {

inline std::string escapeMarkup(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

}  // namespace mms
