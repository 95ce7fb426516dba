#pragma once
/// @file io_test_support.hpp
/// Helpers shared by the io tests: a scratch directory per test, whole-file reads, a base64
/// decoder and a minimal scan of VTK XML DataArray elements (independent of the writer).

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace sinew::io::testing {

/// A fresh, empty directory named after the running test, removed at destruction.
class ScratchDirectory {
 public:
  ScratchDirectory() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("sinew_test_io_" + std::to_string(::getpid()) + "_" + info->test_suite_name() + "_" +
             info->name());
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    std::filesystem::permissions(path_, std::filesystem::perms::owner_all,
                                 std::filesystem::perm_options::add, ignored);
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// `name` inside the directory, as a string.
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

inline std::string read_whole_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

/// Names of the entries of `directory` (not recursive), sorted.
inline std::vector<std::string> directory_entries(const std::filesystem::path& directory) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

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

/// One `<DataArray ...>text</DataArray>` element: its attributes and its text, trimmed.
struct ScannedArray {
  std::map<std::string, std::string> attributes;
  std::string text;
  std::string section;  ///< the enclosing element: "Points", "Cells", "PointData" or "CellData"
};

/// Attributes of the start tag `tag` (the text between '<name' and '>').
inline std::map<std::string, std::string> scan_attributes(const std::string& tag) {
  std::map<std::string, std::string> attributes;
  std::size_t position = 0;
  while (true) {
    const std::size_t equals = tag.find("=\"", position);
    if (equals == std::string::npos) break;
    std::size_t name_start = tag.rfind(' ', equals);
    name_start = (name_start == std::string::npos) ? 0 : name_start + 1;
    const std::size_t value_end = tag.find('"', equals + 2);
    attributes[tag.substr(name_start, equals - name_start)] =
        tag.substr(equals + 2, value_end - equals - 2);
    position = value_end + 1;
  }
  return attributes;
}

/// Every DataArray of a VTU file, in document order.
inline std::vector<ScannedArray> scan_data_arrays(const std::string& xml) {
  std::vector<ScannedArray> arrays;
  std::size_t position = 0;
  while ((position = xml.find("<DataArray", position)) != std::string::npos) {
    ScannedArray array;
    for (const char* section : {"Points", "Cells", "PointData", "CellData"}) {
      const std::size_t open = xml.rfind(std::string("<") + section + ">", position);
      const std::size_t close = xml.rfind(std::string("</") + section + ">", position);
      if (open != std::string::npos && (close == std::string::npos || close < open)) {
        array.section = section;
      }
    }
    const std::size_t tag_end = xml.find('>', position);
    array.attributes = scan_attributes(xml.substr(position, tag_end - position));
    const std::size_t text_end = xml.find("</DataArray>", tag_end);
    std::string text = xml.substr(tag_end + 1, text_end - tag_end - 1);
    text.erase(0, text.find_first_not_of(" \n\t"));
    text.erase(text.find_last_not_of(" \n\t") + 1);
    array.text = text;
    arrays.push_back(array);
    position = text_end;
  }
  return arrays;
}

/// Decodes a format="binary" array with a UInt64 byte-count header into values of type T
/// (little-endian host assumed, as on every machine the tests run on).
template <typename T>
std::vector<T> decode_binary_array(const ScannedArray& array) {
  const std::string bytes = decode_base64(array.text);
  if (bytes.size() < 8) throw std::runtime_error("array shorter than its header");
  std::uint64_t byte_count = 0;
  std::memcpy(&byte_count, bytes.data(), 8);
  if (byte_count != bytes.size() - 8) {
    throw std::runtime_error("header says " + std::to_string(byte_count) + " bytes, found " +
                             std::to_string(bytes.size() - 8));
  }
  if (byte_count % sizeof(T) != 0) throw std::runtime_error("byte count not a multiple of the type size");
  std::vector<T> values(byte_count / sizeof(T));
  if (!values.empty()) std::memcpy(values.data(), bytes.data() + 8, byte_count);
  return values;
}

}  // namespace sinew::io::testing
