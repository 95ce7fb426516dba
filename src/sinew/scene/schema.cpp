/// @file schema.cpp
/// Validation of JSON documents against a Schema, and the small text helpers it needs.

#include "sinew/scene/schema.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <set>

namespace sinew::scene {

using nlohmann::json;

std::string format_number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  // The shortest form that reads back exactly: 5, 0.1, 2147483648, 1e+06, 1e-06, 1e+300 (never
  // the 301 digits of 1e300 written out).
  std::array<char, 64> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

namespace {

bool is_plain_identifier(const std::string& key) {
  if (key.empty()) return false;
  return std::all_of(key.begin(), key.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
}

std::string lowercase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace

std::string json_path_key(const std::string& path, const std::string& key) {
  if (!is_plain_identifier(key)) return path + "[" + json(key).dump() + "]";
  return path.empty() ? key : path + "." + key;
}

std::string json_path_index(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1, 0));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[n][m];
}

std::optional<std::string> closest_match(const std::string& word, const std::vector<std::string>& candidates) {
  std::optional<std::string> best;
  std::size_t best_distance = 3;
  for (const std::string& candidate : candidates) {
    const std::size_t distance = edit_distance(lowercase(word), lowercase(candidate));
    // A distance as large as a word's length would "match" anything that short.
    if (distance >= word.size() || distance >= candidate.size()) continue;
    if (distance < best_distance) {
      best_distance = distance;
      best = candidate;
    }
  }
  return best;
}

namespace {

/// A JSON value in a message: compact, and cut when long.
std::string show(const json& value) {
  std::string text = value.is_number() ? format_number(value.get<double>()) : value.dump();
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return text;
}

std::string quoted_list(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) text += ", ";
    text += json(names[i]).dump();
  }
  return text;
}

std::string describe_type(const SchemaNode& node, const Schema& schema) {
  switch (node.type) {
    case SchemaType::Object:
    case SchemaType::OneOf:
    case SchemaType::Map: return "an object";
    case SchemaType::Array: return "an array";
    case SchemaType::Number: return "a number";
    case SchemaType::Integer: return "an integer";
    case SchemaType::String: return "a string";
    case SchemaType::Boolean: return "true or false";
    case SchemaType::Vec3: return "an array of 3 numbers [x, y, z]";
    case SchemaType::Either: {
      std::string text;
      for (std::size_t i = 0; i < node.items.size(); ++i) {
        if (i > 0) text += i + 1 == node.items.size() ? " or " : ", ";
        text += describe_type(node.items[i], schema);
      }
      return text;
    }
    case SchemaType::Ref: return describe_type(schema.definitions.at(node.ref), schema);
  }
  return "?";
}

/// Whether a value has the JSON kind a node expects (without checking its content).
bool kind_matches(const SchemaNode& node, const json& value, const Schema& schema) {
  switch (node.type) {
    case SchemaType::Object:
    case SchemaType::OneOf:
    case SchemaType::Map: return value.is_object();
    case SchemaType::Array:
    case SchemaType::Vec3: return value.is_array();
    case SchemaType::Number:
    case SchemaType::Integer: return value.is_number();
    case SchemaType::String: return value.is_string();
    case SchemaType::Boolean: return value.is_boolean();
    case SchemaType::Either:
      return std::any_of(node.items.begin(), node.items.end(),
                         [&](const SchemaNode& item) { return kind_matches(item, value, schema); });
    case SchemaType::Ref: return kind_matches(schema.definitions.at(node.ref), value, schema);
  }
  return false;
}

class Validator {
 public:
  explicit Validator(const Schema& schema) : schema_(schema) {}

  std::vector<std::string> errors;

  void check(const SchemaNode& node, json& value, const std::string& path) {
    switch (node.type) {
      case SchemaType::Object:
      case SchemaType::OneOf: check_object(node, value, path); break;
      case SchemaType::Map: check_map(node, value, path); break;
      case SchemaType::Array: check_array(node, value, path); break;
      case SchemaType::Number:
      case SchemaType::Integer: check_number(node, value, path); break;
      case SchemaType::String:
      case SchemaType::Boolean: check_scalar(node, value, path); break;
      case SchemaType::Vec3: check_vec3(node, value, path); break;
      case SchemaType::Either: check_either(node, value, path); break;
      case SchemaType::Ref: check(schema_.definitions.at(node.ref), value, path); break;
    }
  }

 private:
  const Schema& schema_;

  void error(const std::string& path, const std::string& message) {
    errors.push_back((path.empty() ? std::string("(scene)") : path) + ": " + message);
  }

  void type_error(const SchemaNode& node, const json& value, const std::string& path) {
    error(path, "must be " + describe_type(node, schema_) + ", got " + show(value));
  }

  void check_object(const SchemaNode& node, json& value, const std::string& path) {
    if (!value.is_object()) return type_error(node, value, path);

    // The properties in force: common ones, plus those of the variant the tag selects.
    std::vector<const SchemaNode*> active;
    for (const SchemaNode& property : node.properties) active.push_back(&property);
    std::set<std::string> tolerated;  // keys of other variants, when the tag is unusable
    bool tag_usable = true;
    std::string tag_value;
    if (!node.tag_key.empty()) {
      const auto tag = value.find(node.tag_key);
      tag_usable = tag != value.end() && tag->is_string();
      if (tag_usable) {
        tag_value = tag->get<std::string>();
        const auto variant = std::find_if(node.variants.begin(), node.variants.end(),
                                          [&](const SchemaVariant& v) { return v.tag == tag_value; });
        tag_usable = variant != node.variants.end();
        if (tag_usable) {
          for (const SchemaNode& property : variant->properties) active.push_back(&property);
        }
      }
      if (!tag_usable) {
        for (const SchemaVariant& variant : node.variants) {
          for (const SchemaNode& property : variant.properties) tolerated.insert(property.key);
        }
      }
    }

    std::vector<std::string> known;
    for (const SchemaNode* property : active) known.push_back(property->key);
    for (auto it = value.begin(); it != value.end(); ++it) {
      if (std::find(known.begin(), known.end(), it.key()) != known.end()) continue;
      if (tolerated.count(it.key()) > 0) continue;
      std::string message = "unknown key";
      if (!node.tag_key.empty() && tag_usable) {
        message += " for " + node.tag_key + " " + json(tag_value).dump();
      }
      if (const auto suggestion = closest_match(it.key(), known)) {
        message += "; did you mean " + json(*suggestion).dump() + "?";
      } else {
        message += "; allowed keys: " + quoted_list(known);
      }
      error(json_path_key(path, it.key()), message);
    }

    const bool is_alternative_key = node.type == SchemaType::OneOf;
    for (const SchemaNode* property : active) {
      const std::string property_path = json_path_key(path, property->key);
      const bool alternative = is_alternative_key && std::find(node.one_of.begin(), node.one_of.end(),
                                                               property->key) != node.one_of.end();
      auto it = value.find(property->key);
      if (it != value.end()) {
        check(*property, *it, property_path);
      } else if (property->required && !alternative) {
        error(property_path, "missing required key (" + property->doc + ")");
      } else if (property->default_value && !alternative) {
        value[property->key] = *property->default_value;
        check(*property, value[property->key], property_path);  // completes nested defaults
      }
    }

    if (node.type == SchemaType::OneOf) {
      std::vector<std::string> present;
      for (const std::string& key : node.one_of) {
        if (value.contains(key)) present.push_back(key);
      }
      if (present.size() != 1) {
        error(path, "must hold exactly one of " + quoted_list(node.one_of) + "; found " +
                        (present.empty() ? std::string("none") : quoted_list(present)));
      }
    }
  }

  void check_map(const SchemaNode& node, json& value, const std::string& path) {
    if (!value.is_object()) return type_error(node, value, path);
    if (value.size() < node.min_items) {
      error(path, "must hold at least " + std::to_string(node.min_items) + " entr" +
                      (node.min_items == 1 ? "y" : "ies"));
    }
    for (auto it = value.begin(); it != value.end(); ++it) {
      if (!check_no_control_characters(it.key(), json_path_key(path, it.key()), "names")) continue;
      check(node.items.at(0), it.value(), json_path_key(path, it.key()));
    }
  }

  void check_array(const SchemaNode& node, json& value, const std::string& path) {
    if (!value.is_array()) return type_error(node, value, path);
    if (node.min_items == node.max_items && value.size() != node.min_items) {
      error(path, "must hold exactly " + std::to_string(node.min_items) + " elements, got " +
                      std::to_string(value.size()));
    } else if (value.size() < node.min_items) {
      error(path, "must hold at least " + std::to_string(node.min_items) + " element" +
                      (node.min_items == 1 ? "" : "s") + ", got " + std::to_string(value.size()));
    } else if (value.size() > node.max_items) {
      error(path, "must hold at most " + std::to_string(node.max_items) + " elements, got " +
                      std::to_string(value.size()));
    }
    for (std::size_t i = 0; i < value.size(); ++i) check(node.items.at(0), value[i], json_path_index(path, i));
  }

  void check_number(const SchemaNode& node, json& value, const std::string& path) {
    if (!value.is_number()) return type_error(node, value, path);
    const double number = value.get<double>();
    if (!std::isfinite(number)) return error(path, "must be a finite number, got " + show(value));
    std::optional<SchemaBound> minimum = node.minimum, maximum = node.maximum;
    if (node.type == SchemaType::Integer) {
      if (number != std::floor(number)) return type_error(node, value, path);
      // Integers are read into int: without a bound of its own, 2147483648 would wrap.
      if (!minimum) minimum = SchemaBound{static_cast<double>(std::numeric_limits<int>::min()), false};
      if (!maximum) maximum = SchemaBound{static_cast<double>(std::numeric_limits<int>::max()), false};
      if (!value.is_number_integer() && std::abs(number) <= 9e15) value = static_cast<std::int64_t>(number);
    }
    check_bounds(minimum, maximum, number, path, show(value));
  }

  void check_bounds(const std::optional<SchemaBound>& minimum, const std::optional<SchemaBound>& maximum,
                    double number, const std::string& path, const std::string& shown) {
    if (minimum && (minimum->exclusive ? !(number > minimum->value) : !(number >= minimum->value))) {
      error(path, std::string("must be ") + (minimum->exclusive ? "> " : ">= ") + format_number(minimum->value) +
                      ", got " + shown);
    }
    if (maximum && (maximum->exclusive ? !(number < maximum->value) : !(number <= maximum->value))) {
      error(path, std::string("must be ") + (maximum->exclusive ? "< " : "<= ") + format_number(maximum->value) +
                      ", got " + shown);
    }
  }

  /// Names, paths and choices may not hold control characters (a NUL would cut messages).
  bool check_no_control_characters(const std::string& text, const std::string& path, const char* what) {
    const bool has_control = std::any_of(text.begin(), text.end(), [](char c) {
      return static_cast<unsigned char>(c) < 0x20;
    });
    if (has_control) {
      error(path, std::string(what) + " may not contain control characters (codes below 0x20), got " +
                      json(text).dump());
    }
    return !has_control;
  }

  void check_scalar(const SchemaNode& node, json& value, const std::string& path) {
    const bool kind_ok = node.type == SchemaType::String ? value.is_string() : value.is_boolean();
    if (!kind_ok) return type_error(node, value, path);
    if (node.non_empty && value.get<std::string>().empty()) return error(path, "must not be empty");
    if (node.type == SchemaType::String && !node.free_text &&
        !check_no_control_characters(value.get<std::string>(), path, "names")) {
      return;
    }
    if (node.allowed.empty()) return;
    if (std::find(node.allowed.begin(), node.allowed.end(), value) != node.allowed.end()) return;
    std::vector<std::string> shown;
    for (const json& allowed : node.allowed) shown.push_back(allowed.dump());
    std::string list;
    for (std::size_t i = 0; i < shown.size(); ++i) list += (i > 0 ? ", " : "") + shown[i];
    std::string message = (shown.size() == 1 ? "must be " : "must be one of ") + list + ", got " + show(value);
    if (value.is_string()) {
      std::vector<std::string> names;
      for (const json& allowed : node.allowed) {
        if (allowed.is_string()) names.push_back(allowed.get<std::string>());
      }
      if (const auto suggestion = closest_match(value.get<std::string>(), names)) {
        message += "; did you mean " + json(*suggestion).dump() + "?";
      }
    }
    error(path, message);
  }

  void check_vec3(const SchemaNode& node, json& value, const std::string& path) {
    const bool shape_ok = value.is_array() && value.size() == 3 &&
                          std::all_of(value.begin(), value.end(), [](const json& x) { return x.is_number(); });
    if (!shape_ok) return type_error(node, value, path);
    for (const json& x : value) {
      if (!std::isfinite(x.get<double>())) return error(path, "must hold finite numbers, got " + show(value));
    }
    for (std::size_t i = 0; i < 3; ++i) {
      check_bounds(node.minimum, node.maximum, value[i].get<double>(), json_path_index(path, i), show(value[i]));
    }
    if (node.nonzero && std::all_of(value.begin(), value.end(), [](const json& x) { return x.get<double>() == 0; })) {
      error(path, "must not be the zero vector");
    }
  }

  void check_either(const SchemaNode& node, json& value, const std::string& path) {
    for (const SchemaNode& alternative : node.items) {
      if (kind_matches(alternative, value, schema_)) return check(alternative, value, path);
    }
    type_error(node, value, path);
  }
};

}  // namespace

SchemaValidation validate_and_complete(const Schema& schema, const json& document) {
  SchemaValidation result;
  result.completed = document;
  Validator validator(schema);
  validator.check(schema.root, result.completed, "");
  result.errors = std::move(validator.errors);
  return result;
}

}  // namespace sinew::scene
