#pragma once
/// @file enum_names.hpp
/// Names of enumerations as the user writes them (scene files, the command line), each
/// written once: beside its enum, a table
///
///     inline constexpr NameTable<ContactMethod, 2> kContactMethodNames{{
///         {ContactMethod::Area, "area"}, {ContactMethod::Point, "point"}}};
///     constexpr const auto& enum_names(ContactMethod) { return kContactMethodNames; }
///
/// The overload `enum_names(E)` is found by argument-dependent lookup, so the helpers below work
/// for every enum that has one: the scene schema lists the allowed values from it, the scene
/// reader parses strictly with it, and the command line checks its options against it
/// (docs/scene-reference.md shows the lists).

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace sinew {

/// The names of an enum's values, in documentation order. Names are string literals, so
/// `name.data()` is NUL-terminated.
template <typename E, std::size_t N>
using NameTable = std::array<std::pair<E, std::string_view>, N>;

/// An enum with a name table (an `enum_names(E)` overload reachable by argument-dependent lookup).
template <typename E>
concept NamedEnum = std::is_enum_v<E> && requires(E value) {
  { enum_names(value).front().second } -> std::convertible_to<std::string_view>;
};

/// The name of `value`; "?" for a value outside the table (a cast of a bad integer).
template <NamedEnum E>
constexpr std::string_view name_of(E value) {
  for (const auto& [entry, name] : enum_names(value)) {
    if (entry == value) return name;
  }
  return "?";
}

/// The value named `name` (exact, case-sensitive match), or nothing.
template <NamedEnum E>
constexpr std::optional<E> parse_name(std::string_view name) {
  for (const auto& [entry, entry_name] : enum_names(E{})) {
    if (entry_name == name) return entry;
  }
  return std::nullopt;
}

/// Every name of E, in table order.
template <NamedEnum E>
std::vector<std::string> names_of() {
  std::vector<std::string> names;
  for (const auto& entry : enum_names(E{})) names.emplace_back(entry.second);
  return names;
}

/// The names for messages: "\"area\", \"point\"".
template <NamedEnum E>
std::string names_list() {
  std::string text;
  for (const auto& entry : enum_names(E{})) {
    if (!text.empty()) text += ", ";
    text += "\"";
    text += entry.second;
    text += "\"";
  }
  return text;
}

}  // namespace sinew
