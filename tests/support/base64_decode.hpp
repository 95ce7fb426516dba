#pragma once
/// @file base64_decode.hpp
/// A base64 decoder for tests that read the binary arrays of .vtu files, independent of the
/// library's encoder (sinew/io/base64.hpp).

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace sinew::testing {

/// Decodes standard base64 with '=' padding; throws on characters outside the alphabet.
inline std::string decode_base64(const std::string& text) {
  auto value_of = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    throw std::runtime_error(std::string("invalid base64 character '") + c + "'");
  };
  if (text.size() % 4 != 0) throw std::runtime_error("base64 length is not a multiple of 4");
  std::string out;
  for (std::size_t i = 0; i < text.size(); i += 4) {
    std::uint32_t bits = 0;
    int padding = 0;
    for (std::size_t j = 0; j < 4; ++j) {
      bits <<= 6;
      if (text[i + j] == '=') {
        ++padding;
      } else {
        if (padding > 0) throw std::runtime_error("base64 data after padding");
        bits |= static_cast<std::uint32_t>(value_of(text[i + j]));
      }
    }
    out.push_back(static_cast<char>((bits >> 16) & 0xFF));
    if (padding < 2) out.push_back(static_cast<char>((bits >> 8) & 0xFF));
    if (padding < 1) out.push_back(static_cast<char>(bits & 0xFF));
  }
  return out;
}

}  // namespace sinew::testing
