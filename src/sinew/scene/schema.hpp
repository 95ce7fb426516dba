#pragma once
/// @file schema.hpp
/// A declarative schema for JSON input: a tree of plain structs that says, for every key, its
/// type, whether it is required, its default, its range or allowed values, and a one-line
/// description. One schema object drives validation (validate_and_complete), the Markdown
/// reference (schema_markdown_tables) and the JSON Schema export (to_json_schema).
///
/// The scene's schema itself is in scene_schema.hpp.

#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sinew::scene {

/// Kinds of schema nodes.
enum class SchemaType {
  Object,   ///< fixed keys (`properties`); unknown keys are rejected; optionally tagged (`tag_key`)
  Map,      ///< free keys (names), every value follows `items[0]`
  Array,    ///< every element follows `items[0]`; size in [min_items, max_items]
  Number,   ///< finite number
  Integer,  ///< number with no fractional part, within the range of int unless bounded otherwise
  String,
  Boolean,
  Vec3,     ///< array of exactly 3 finite numbers
  OneOf,    ///< an object with exactly one of the keys named in `one_of` (and any other properties)
  Either,   ///< a value matching one of `items` chosen by its JSON type (string, object, ...)
  Ref,      ///< the definition named `ref` (see Schema::definitions), used for recursion and reuse
};

/// An inclusive or exclusive numeric bound.
struct SchemaBound {
  double value = 0;
  bool exclusive = false;
};

struct SchemaVariant;

/// One node of the schema tree. Which fields matter depends on `type` (see SchemaType).
struct SchemaNode {
  SchemaType type = SchemaType::Object;
  std::string key;   ///< the key in the parent object; empty for items, map values, definitions
  std::string doc;   ///< one line, with units where relevant
  bool required = false;
  std::optional<nlohmann::json> default_value;  ///< filled in when the key is omitted

  // Number, Integer; Vec3: bounds on each component. An Integer without a bound of its own is
  // bounded by the range of int, the type integers are read into.
  std::optional<SchemaBound> minimum;
  std::optional<SchemaBound> maximum;
  // String, Boolean: allowed values (empty = any)
  std::vector<nlohmann::json> allowed;
  bool non_empty = false;  ///< String: must not be ""
  /// String: may hold control characters (code < 0x20: NUL, newline, ...), as free text may.
  /// Other strings (names, paths, choices) and every Map key may not: a NUL would cut messages.
  bool free_text = false;
  bool nonzero = false;    ///< Vec3: must not be [0, 0, 0]

  // Object, OneOf: the keys, in documentation order
  std::vector<SchemaNode> properties;
  // OneOf: exactly one of these keys (each also listed in `properties`)
  std::vector<std::string> one_of;
  // Tagged Object: the value of the string property `tag_key` selects extra properties
  std::string tag_key;
  std::vector<SchemaVariant> variants;

  // Array, Map: items[0] is the element schema. Either: the alternatives.
  std::vector<SchemaNode> items;
  std::size_t min_items = 0;
  std::size_t max_items = std::numeric_limits<std::size_t>::max();

  std::string ref;  ///< Ref: name of the definition
};

/// One alternative of a tagged object: `tag_key` == tag adds these properties.
struct SchemaVariant {
  std::string tag;
  std::string doc;
  std::vector<SchemaNode> properties;
};

/// A root node plus named definitions that Ref nodes point to.
struct Schema {
  std::string title;  ///< shown in the JSON Schema export
  SchemaNode root;
  std::map<std::string, SchemaNode> definitions;
};

/// Validates `document` against `schema` and returns a copy in which every omitted key that has
/// a default holds it, and integers written as 4.0 are stored as integers. Collects every error
/// as "<json path>: <what is wrong>" (e.g. "bodies[0].regions.muscle.density: must be >= 0, got
/// -1"); returns them in document order. Does not throw.
struct SchemaValidation {
  nlohmann::json completed;
  std::vector<std::string> errors;
};
SchemaValidation validate_and_complete(const Schema& schema, const nlohmann::json& document);

/// The schema as a JSON Schema (draft-07) document; Ref nodes become "$ref" to "definitions".
nlohmann::json to_json_schema(const Schema& schema);

/// Markdown tables: one section per object (headed by its JSON path, e.g. `bodies[].mesh`), one
/// row per key: key, type, default ("required" when required), range or allowed values, and
/// description. Each definition gets a section, linked from the keys that refer to it.
std::string schema_markdown_tables(const Schema& schema);

/// Renders a number the way messages and docs show it: the shortest form that reads back exactly
/// (5, 0.1, 2147483648, 1e+06, 1e-06, 1e+300), integers without a decimal point.
std::string format_number(double value);

/// Appends a key or index to a JSON path: "a" + "b" -> "a.b"; keys that are not plain
/// identifiers are quoted: "regions" + "*" -> regions["*"].
std::string json_path_key(const std::string& path, const std::string& key);
std::string json_path_index(const std::string& path, std::size_t index);

/// Optimal-string-alignment edit distance (insertions, deletions, substitutions and adjacent
/// transpositions count 1 each).
std::size_t edit_distance(const std::string& a, const std::string& b);

/// The candidate closest to `word` within edit distance 2 (case-insensitive), if any; a
/// distance as large as either word's length does not count ("c" does not suggest "a").
std::optional<std::string> closest_match(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace sinew::scene
