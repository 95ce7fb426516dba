#pragma once
/// @file msh_cursor.hpp
/// A reader of MSH files for msh_format_check.cpp: lines, whitespace-separated tokens and raw
/// binary values, every problem an InputError naming the file. Not a mesh reader: it only walks
/// a file far enough to check the counts and tags Gmsh would trust (docs/input-safety.md).

#include <charconv>
#include <cstdint>
#include <fstream>
#include <string>
#include <system_error>

#include "sinew/core/error.hpp"

namespace sinew::mesh {

/// Reads an MSH file as lines, whitespace-separated tokens or raw binary values, reporting
/// every problem as an InputError that names the file.
class MshCursor {
 public:
  /// Reads `path`, `size` bytes long; messages name `shown_path`.
  MshCursor(const std::string& path, std::uintmax_t size, const std::string& shown_path)
      : in_(path, std::ios::binary), size_(size), context_("mesh file \"" + shown_path + "\"") {
    if (!in_) fail(" cannot be opened for reading");
  }

  [[noreturn]] void fail(const std::string& problem) const { throw InputError(context_ + problem); }

  /// The next line without its end-of-line characters; false at the end of the file.
  bool next_line(std::string& line) {
    if (!std::getline(in_, line)) return false;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) {
      line.pop_back();
    }
    return true;
  }

  /// Skips the rest of the current line.
  void skip_line() {
    std::string rest;
    std::getline(in_, rest);
  }

  std::uintmax_t remaining() {
    const auto position = in_.tellg();
    if (position < 0) return 0;
    const auto used = static_cast<std::uintmax_t>(position);
    return used < size_ ? size_ - used : 0;
  }

  /// An ASCII count (a non-negative integer) of `section`.
  std::uint64_t ascii_count(const std::string& section) {
    std::string token;
    if (!(in_ >> token)) truncated(section);
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size()) {
      fail(" is malformed: its $" + section + " section holds \"" + token.substr(0, 40) +
           "\" where a count (a non-negative integer) belongs");
    }
    return value;
  }

  /// A count of a version 4 section: 8 bytes in a binary file, an integer in an ASCII one.
  std::uint64_t v4_count(bool binary_file, const std::string& section) {
    return binary_file ? binary<std::uint64_t>(section) : ascii_count(section);
  }
  /// An entity dimension, tag or element type of a version 4 section: 4 bytes or an integer.
  std::uint64_t v4_small(bool binary_file, const std::string& section) {
    return binary_file ? static_cast<std::uint64_t>(binary<std::int32_t>(section)) : ascii_count(section);
  }

  void skip_tokens(std::uint64_t count, const std::string& section) {
    std::string token;
    for (std::uint64_t i = 0; i < count; ++i) {
      if (!(in_ >> token)) truncated(section);
    }
  }

  template <class T>
  T binary(const std::string& section) {
    T value{};
    if (!in_.read(reinterpret_cast<char*>(&value), sizeof(T))) truncated(section);
    return value;
  }

  void skip_bytes(std::uint64_t count, const std::string& section) {
    if (count > remaining()) truncated(section);
    in_.seekg(static_cast<std::streamoff>(count), std::ios::cur);
  }

  /// Throws unless `count` items of at least `bytes_each` bytes fit in the rest of the file.
  void check_fits(std::uint64_t count, std::uint64_t bytes_each, const std::string& what,
                  const std::string& section) {
    const std::uintmax_t left = remaining();
    if (count > left / bytes_each) {
      fail(" is malformed or truncated: its $" + section + " section announces " +
           std::to_string(count) + " " + what + ", more than the " + std::to_string(left) +
           " bytes that follow can hold (a count in its header is larger than the file)");
    }
  }

  [[noreturn]] void truncated(const std::string& section) const {
    fail(" is truncated or malformed: it ends inside its $" + section +
         " section, before the data its header announces (re-export it from Gmsh)");
  }

 private:
  std::ifstream in_;
  std::uintmax_t size_;
  std::string context_;
};

}  // namespace sinew::mesh
