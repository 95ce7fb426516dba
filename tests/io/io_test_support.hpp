#pragma once
/// @file io_test_support.hpp
/// Helpers shared by the io tests: a minimal scan of VTK XML DataArray elements (independent of
/// the writer) and the decoding of their binary arrays; TempDir, read_text and decode_base64
/// come from tests/support.

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

#include "support/base64_decode.hpp"
#include "support/files.hpp"
#include "support/temp_dir.hpp"

namespace sinew::io::testing {

using sinew::testing::decode_base64;
using sinew::testing::read_text;
using sinew::testing::TempDir;

/// Names of the entries of `directory` (not recursive), sorted.
inline std::vector<std::string> directory_entries(const std::filesystem::path& directory) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
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
