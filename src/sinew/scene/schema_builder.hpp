#pragma once
/// @file schema_builder.hpp
/// Small fluent helpers that build SchemaNode trees, so a schema (scene_schema.cpp) reads like
/// the reference it produces: `number("density", "mass / length^3").min(0).fallback(0)`.

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "sinew/core/enum_names.hpp"
#include "sinew/core/types.hpp"
#include "sinew/scene/schema.hpp"

namespace sinew::scene::schema_builder {

using nlohmann::json;

/// A schema node under construction; converts to SchemaNode.
struct Key {
  SchemaNode node;

  Key(SchemaType type, std::string key, std::string doc) {
    node.type = type;
    node.key = std::move(key);
    node.doc = std::move(doc);
  }
  Key& required() {
    node.required = true;
    return *this;
  }
  Key& fallback(json value) {
    node.default_value = std::move(value);
    return *this;
  }
  Key& min(double value, bool exclusive = false) {
    node.minimum = SchemaBound{value, exclusive};
    return *this;
  }
  Key& max(double value, bool exclusive = false) {
    node.maximum = SchemaBound{value, exclusive};
    return *this;
  }
  /// Bounds the value (every component of a vec3) to [-limit, limit].
  Key& within(double limit) { return min(-limit).max(limit); }
  /// Strings that may hold control characters (free text: newlines, tabs).
  Key& free_text() {
    node.free_text = true;
    return *this;
  }
  Key& above(double value) { return min(value, true); }
  Key& below(double value) { return max(value, true); }
  Key& allowed(std::vector<json> values) {
    node.allowed = std::move(values);
    return *this;
  }
  Key& non_empty() {
    node.non_empty = true;
    return *this;
  }
  Key& nonzero() {
    node.nonzero = true;
    return *this;
  }
  Key& items(std::size_t min_count, std::size_t max_count = std::numeric_limits<std::size_t>::max()) {
    node.min_items = min_count;
    node.max_items = max_count;
    return *this;
  }
  operator SchemaNode() const { return node; }  // NOLINT(google-explicit-constructor)
};

inline Key number(std::string key, std::string doc) { return Key(SchemaType::Number, std::move(key), std::move(doc)); }
inline Key integer(std::string key, std::string doc) { return Key(SchemaType::Integer, std::move(key), std::move(doc)); }
inline Key string(std::string key, std::string doc) { return Key(SchemaType::String, std::move(key), std::move(doc)); }
inline Key boolean(std::string key, std::string doc) { return Key(SchemaType::Boolean, std::move(key), std::move(doc)); }
inline Key vec3(std::string key, std::string doc) { return Key(SchemaType::Vec3, std::move(key), std::move(doc)); }

inline Key object(std::string key, std::string doc, std::vector<SchemaNode> properties) {
  Key k(SchemaType::Object, std::move(key), std::move(doc));
  k.node.properties = std::move(properties);
  return k;
}

inline Key one_of(std::string key, std::string doc, std::vector<SchemaNode> properties, std::vector<std::string> alternatives) {
  Key k(SchemaType::OneOf, std::move(key), std::move(doc));
  k.node.properties = std::move(properties);
  k.node.one_of = std::move(alternatives);
  return k;
}

inline Key array(std::string key, std::string doc, SchemaNode element) {
  Key k(SchemaType::Array, std::move(key), std::move(doc));
  k.node.items = {std::move(element)};
  return k;
}

inline Key map(std::string key, std::string doc, SchemaNode value) {
  Key k(SchemaType::Map, std::move(key), std::move(doc));
  k.node.items = {std::move(value)};
  return k;
}

inline Key either(std::string key, std::string doc, std::vector<SchemaNode> alternatives) {
  Key k(SchemaType::Either, std::move(key), std::move(doc));
  k.node.items = std::move(alternatives);
  return k;
}

inline Key ref(std::string key, std::string doc, std::string definition) {
  Key k(SchemaType::Ref, std::move(key), std::move(doc));
  k.node.ref = std::move(definition);
  return k;
}

inline json vec3_json(const Vector3& v) { return json::array({v.x(), v.y(), v.z()}); }

/// The names of E's values (its name table, sinew/core/enum_names.hpp) as allowed values.
template <NamedEnum E>
std::vector<json> allowed_names() {
  std::vector<json> names;
  for (const auto& entry : enum_names(E{})) names.emplace_back(std::string(entry.second));
  return names;
}

/// A string naming one of E's values, `fallback_value` when omitted.
template <NamedEnum E>
Key choice(std::string key, std::string doc, E fallback_value) {
  return string(std::move(key), std::move(doc)).allowed(allowed_names<E>()).fallback(std::string(name_of(fallback_value)));
}

/// The name of `value` as a std::string (for keys and tags named by an enum's name table).
template <NamedEnum E>
std::string key_of(E value) {
  return std::string(name_of(value));
}

}  // namespace sinew::scene::schema_builder
