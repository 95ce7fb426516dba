#pragma once
/// @file base64.hpp
/// Base64 encoding (RFC 4648, standard alphabet, '=' padding, no line breaks), as used by
/// the inline binary data arrays of VTK XML files.

#include <cstddef>
#include <string>
#include <string_view>

namespace sinew::io {

/// Appends the base64 encoding of `size` bytes at `data` to `out`
/// (4 * ceil(size / 3) characters).
void append_base64(std::string& out, const void* data, std::size_t size);

/// The base64 encoding of `bytes`.
std::string encode_base64(std::string_view bytes);

}  // namespace sinew::io
