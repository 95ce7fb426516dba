#pragma once
/// @file xml_escape.hpp
/// Text for XML attribute values (the VTK files' array and file names).

#include <string>
#include <string_view>

namespace sinew::io {

/// `text` with the five XML special characters replaced by entities.
inline std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace sinew::io
