/// @file schema_export.cpp
/// A Schema rendered as a JSON Schema (draft-07) document and as Markdown tables.

#include <algorithm>
#include <cctype>
#include <limits>
#include <sstream>

#include "sinew/scene/schema.hpp"

namespace sinew::scene {

using nlohmann::json;

namespace {

// ---------------------------------------------------------------- JSON Schema (draft-07)

json bound_json(const SchemaNode& node) {
  json out = json::object();
  if (node.minimum) out[node.minimum->exclusive ? "exclusiveMinimum" : "minimum"] = node.minimum->value;
  if (node.maximum) out[node.maximum->exclusive ? "exclusiveMaximum" : "maximum"] = node.maximum->value;
  return out;
}

json node_json(const SchemaNode& node);

/// "properties", "required" and "additionalProperties": false for a list of keys.
void add_properties(json& out, const std::vector<const SchemaNode*>& properties, const std::vector<std::string>& one_of) {
  out["properties"] = json::object();
  json required = json::array();
  for (const SchemaNode* property : properties) {
    out["properties"][property->key] = node_json(*property);
    const bool alternative = std::find(one_of.begin(), one_of.end(), property->key) != one_of.end();
    if (property->required && !alternative) required.push_back(property->key);
  }
  if (!required.empty()) out["required"] = required;
  out["additionalProperties"] = false;
}

json node_json(const SchemaNode& node) {
  json out = json::object();
  switch (node.type) {
    case SchemaType::Object: {
      out["type"] = "object";
      std::vector<const SchemaNode*> common;
      for (const SchemaNode& property : node.properties) common.push_back(&property);
      if (node.tag_key.empty()) {
        add_properties(out, common, {});
        break;
      }
      // Tagged: one closed alternative per variant, the tag fixed to its value.
      out["oneOf"] = json::array();
      for (const SchemaVariant& variant : node.variants) {
        std::vector<const SchemaNode*> all = common;
        for (const SchemaNode& property : variant.properties) all.push_back(&property);
        json alternative = json::object();
        alternative["description"] = variant.doc;
        add_properties(alternative, all, {});
        alternative["properties"][node.tag_key] = json{{"const", variant.tag}};
        out["oneOf"].push_back(alternative);
      }
      break;
    }
    case SchemaType::OneOf: {
      out["type"] = "object";
      std::vector<const SchemaNode*> all;
      for (const SchemaNode& property : node.properties) all.push_back(&property);
      add_properties(out, all, node.one_of);
      out["oneOf"] = json::array();
      for (const std::string& key : node.one_of) out["oneOf"].push_back(json{{"required", json::array({key})}});
      break;
    }
    case SchemaType::Map:
      out["type"] = "object";
      out["additionalProperties"] = node_json(node.items.at(0));
      if (node.min_items > 0) out["minProperties"] = node.min_items;
      break;
    case SchemaType::Array:
      out["type"] = "array";
      out["items"] = node_json(node.items.at(0));
      if (node.min_items > 0) out["minItems"] = node.min_items;
      if (node.max_items != std::numeric_limits<std::size_t>::max()) out["maxItems"] = node.max_items;
      break;
    case SchemaType::Number:
    case SchemaType::Integer:
      out["type"] = node.type == SchemaType::Number ? "number" : "integer";
      out.update(bound_json(node));
      break;
    case SchemaType::String:
    case SchemaType::Boolean:
      out["type"] = node.type == SchemaType::String ? "string" : "boolean";
      if (!node.allowed.empty()) out["enum"] = node.allowed;
      if (node.non_empty) out["minLength"] = 1;
      break;
    case SchemaType::Vec3:
      out["type"] = "array";
      out["items"] = json{{"type", "number"}};
      out["items"].update(bound_json(node));
      out["minItems"] = 3;
      out["maxItems"] = 3;
      if (node.nonzero) out["not"] = json{{"const", json::array({0, 0, 0})}};
      break;
    case SchemaType::Either:
      out["oneOf"] = json::array();
      for (const SchemaNode& alternative : node.items) out["oneOf"].push_back(node_json(alternative));
      break;
    case SchemaType::Ref:
      out["$ref"] = "#/definitions/" + node.ref;
      break;
  }
  if (!node.doc.empty()) out["description"] = node.doc;
  if (node.default_value) out["default"] = *node.default_value;
  return out;
}

// ---------------------------------------------------------------- Markdown

std::string anchor_of(const std::string& path) {
  std::string anchor;
  for (char c : path) {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      anchor += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else if (!anchor.empty() && anchor.back() != '-') {
      anchor += '-';
    }
  }
  while (!anchor.empty() && anchor.back() == '-') anchor.pop_back();
  return anchor.empty() ? "top-level" : anchor;
}

/// Text safe in Markdown: "<name>" cannot open an HTML tag; in table cells "|" cannot end the cell.
std::string escape_text(const std::string& text, bool in_table) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const bool opens_tag = c == '<' && i + 1 < text.size() &&
                           (std::isalpha(static_cast<unsigned char>(text[i + 1])) || text[i + 1] == '/' || text[i + 1] == '!');
    if (opens_tag) {
      out += "&lt;";
    } else if (c == '|' && in_table) {
      out += "\\|";
    } else {
      out += c;
    }
  }
  return out;
}

std::string escape_cell(const std::string& text) { return escape_text(text, true); }

/// Compact JSON with numbers as format_number writes them: [0, 0, 1] rather than [0.0,0.0,1.0].
std::string compact_json(const json& value) {
  if (value.is_number()) return format_number(value.get<double>());
  if (value.is_array()) {
    std::string text = "[";
    for (std::size_t i = 0; i < value.size(); ++i) {
      if (i > 0) text.append(", ");
      text.append(compact_json(value[i]));
    }
    text.append("]");
    return text;
  }
  return value.dump();
}

bool has_section(const SchemaNode& node) {
  return node.type == SchemaType::Object || node.type == SchemaType::OneOf;
}

class MarkdownWriter {
 public:
  explicit MarkdownWriter(const Schema& schema) : schema_(schema) {}

  std::string render() {
    section("(top level)", "top-level", schema_.root);
    for (const auto& [name, definition] : schema_.definitions) {
      definition_section(name, definition);
    }
    return out_.str();
  }

 private:
  const Schema& schema_;
  std::ostringstream out_;

  static std::string definition_anchor(const std::string& name) { return "def-" + anchor_of(name); }

  /// The section path of a child: where its table lives.
  static std::string child_path(const std::string& path, const std::string& key) {
    return path == "(top level)" ? key : path + "." + key;
  }

  std::string type_text(const SchemaNode& node, const std::string& path) {
    switch (node.type) {
      case SchemaType::Object: return "[object](#" + anchor_of(path) + ")";
      case SchemaType::OneOf: return "[one-of](#" + anchor_of(path) + ")";
      case SchemaType::Map: return "map: name → " + type_text(node.items.at(0), path + ".<name>");
      case SchemaType::Array: {
        std::string text = node.min_items == node.max_items ? std::to_string(node.min_items) + "-element array of "
                                                            : std::string("array of ");
        return text.append(type_text(node.items.at(0), path + "[]"));
      }
      case SchemaType::Number: return "number";
      case SchemaType::Integer: return "integer";
      case SchemaType::String: return "string";
      case SchemaType::Boolean: return "boolean";
      case SchemaType::Vec3: return "vec3";
      case SchemaType::Either: {
        std::string text;
        for (std::size_t i = 0; i < node.items.size(); ++i) {
          text += (i > 0 ? " or " : "") + type_text(node.items[i], path);
        }
        return text;
      }
      case SchemaType::Ref: return "[" + node.ref + "](#" + definition_anchor(node.ref) + ")";
    }
    return "?";
  }

  static std::string bound_text(const char* relation, double value) {
    std::string text(relation);
    text.append(format_number(value));
    return text;
  }

  static std::string range_text(const SchemaNode& node) {
    std::vector<std::string> parts;
    const std::string each = node.type == SchemaType::Vec3 ? "each " : "";  // Vec3: bounds on every component
    if (node.minimum) parts.push_back(each + bound_text(node.minimum->exclusive ? "> " : ">= ", node.minimum->value));
    if (node.maximum) parts.push_back(each + bound_text(node.maximum->exclusive ? "< " : "<= ", node.maximum->value));
    if (!node.allowed.empty()) {
      std::string list;
      for (std::size_t i = 0; i < node.allowed.size(); ++i) {
        if (i > 0) list.append(", ");
        list.append("`").append(node.allowed[i].dump()).append("`");
      }
      parts.push_back(list);
    }
    if (node.non_empty) parts.push_back("non-empty");
    if (node.nonzero) parts.push_back("non-zero");
    if (node.type == SchemaType::Array || node.type == SchemaType::Map) {
      const bool bounded = node.max_items != std::numeric_limits<std::size_t>::max();
      if (bounded && node.max_items == node.min_items) {
        parts.push_back("exactly " + std::to_string(node.min_items) + " elements");
      } else {
        if (node.min_items > 0) parts.push_back("at least " + std::to_string(node.min_items));
        if (bounded) parts.push_back("at most " + std::to_string(node.max_items));
      }
    }
    if (node.type == SchemaType::Either) {
      for (const SchemaNode& alternative : node.items) {
        const std::string text = range_text(alternative);
        if (!text.empty()) parts.push_back(text);
      }
    }
    std::string text;
    for (std::size_t i = 0; i < parts.size(); ++i) text += (i > 0 ? "; " : "") + parts[i];
    return text;
  }

  static std::string default_text(const SchemaNode& node) {
    if (node.required) return "**required**";
    if (!node.default_value) return "";
    std::string text = "`";
    text.append(compact_json(*node.default_value)).append("`");
    return text;
  }

  void table(const std::vector<const SchemaNode*>& properties, const std::string& path, const std::vector<std::string>& one_of) {
    out_ << "| Key | Type | Default | Range / values | Description |\n";
    out_ << "| --- | --- | --- | --- | --- |\n";
    for (const SchemaNode* property : properties) {
      const bool alternative = std::find(one_of.begin(), one_of.end(), property->key) != one_of.end();
      out_ << "| `" << property->key << "` | " << type_text(*property, child_path(path, property->key)) << " | "
           << (alternative ? "one of" : default_text(*property)) << " | " << escape_cell(range_text(*property)) << " | "
           << escape_cell(property->doc) << " |\n";
    }
    out_ << "\n";
  }

  void heading(const std::string& title, const std::string& anchor, const std::string& doc) {
    out_ << "<a id=\"" << anchor << "\"></a>\n\n### " << title << "\n\n";
    if (!doc.empty()) out_ << escape_text(doc, false) << "\n\n";
  }

  /// A section for an object node, then the sections of its nested objects.
  void section(const std::string& path, const std::string& anchor, const SchemaNode& node) {
    heading(path == "(top level)" ? "Top level" : "`" + path + "`", anchor, node.doc);
    body(path, node);
  }

  void body(const std::string& path, const SchemaNode& node) {
    if (node.type == SchemaType::OneOf) {
      out_ << "Exactly one of ";
      for (std::size_t i = 0; i < node.one_of.size(); ++i) out_ << (i > 0 ? ", " : "") << "`" << node.one_of[i] << "`";
      out_ << ".\n\n";
    }
    std::vector<const SchemaNode*> common;
    for (const SchemaNode& property : node.properties) common.push_back(&property);
    table(common, path, node.one_of);
    for (const SchemaVariant& variant : node.variants) {
      out_ << "With `" << node.tag_key << "` = `\"" << variant.tag << "\"`: " << escape_text(variant.doc, false) << "\n\n";
      std::vector<const SchemaNode*> own;
      for (const SchemaNode& property : variant.properties) own.push_back(&property);
      if (own.empty()) {
        out_ << "(no further keys)\n\n";
      } else {
        table(own, path, {});
      }
    }
    for (const SchemaNode& property : node.properties) nested(child_path(path, property.key), property);
    for (const SchemaVariant& variant : node.variants) {
      for (const SchemaNode& property : variant.properties) nested(child_path(path, property.key), property);
    }
  }

  /// Sections for the objects inside a value (directly, or as map values or array elements).
  void nested(const std::string& path, const SchemaNode& node) {
    switch (node.type) {
      case SchemaType::Object:
      case SchemaType::OneOf: section(path, anchor_of(path), node); break;
      case SchemaType::Map: nested(path + ".<name>", node.items.at(0)); break;
      case SchemaType::Array: nested(path + "[]", node.items.at(0)); break;
      case SchemaType::Either:
        for (const SchemaNode& alternative : node.items) nested(path, alternative);
        break;
      default: break;
    }
  }

  void definition_section(const std::string& name, const SchemaNode& node) {
    heading(name, definition_anchor(name), node.doc);
    if (has_section(node)) {
      body(name, node);
      return;
    }
    out_ << "Type: " << type_text(node, name);
    const std::string range = range_text(node);
    if (!range.empty()) out_ << "; " << range;
    out_ << ".\n\n";
    nested(name, node);
  }
};

}  // namespace

json to_json_schema(const Schema& schema) {
  json out = node_json(schema.root);
  out["$schema"] = "http://json-schema.org/draft-07/schema#";
  out["title"] = schema.title;
  out["definitions"] = json::object();
  for (const auto& [name, definition] : schema.definitions) out["definitions"][name] = node_json(definition);
  return out;
}

std::string schema_markdown_tables(const Schema& schema) { return MarkdownWriter(schema).render(); }

}  // namespace sinew::scene
