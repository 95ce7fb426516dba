/// @file test_schema.cpp
/// The generic schema machinery: validation of each node type, defaults, message helpers,
/// JSON Schema export.

#include <gtest/gtest.h>

#include "sinew/scene/schema.hpp"

namespace sinew::scene {
namespace {

using nlohmann::json;

SchemaNode leaf(SchemaType type, const std::string& key) {
  SchemaNode node;
  node.type = type;
  node.key = key;
  node.doc = key + " doc";
  return node;
}

/// {"count": integer >= 1 (default 3), "ratio": number in (0, 1], "mode": "a" | "b",
///  "where": vec3 non-zero, "list": [number, ...] (1 to 2), "pick": one of {"x", "y"},
///  "names": map of booleans, "either": string or number}
Schema small_schema() {
  Schema schema;
  SchemaNode& root = schema.root;
  root.type = SchemaType::Object;
  SchemaNode count = leaf(SchemaType::Integer, "count");
  count.minimum = SchemaBound{1, false};
  count.default_value = 3;
  SchemaNode ratio = leaf(SchemaType::Number, "ratio");
  ratio.minimum = SchemaBound{0, true};
  ratio.maximum = SchemaBound{1, false};
  ratio.required = true;
  SchemaNode mode = leaf(SchemaType::String, "mode");
  mode.allowed = {"alpha", "beta"};
  SchemaNode where = leaf(SchemaType::Vec3, "where");
  where.nonzero = true;
  SchemaNode list = leaf(SchemaType::Array, "list");
  list.items = {leaf(SchemaType::Number, "")};
  list.min_items = 1;
  list.max_items = 2;
  SchemaNode pick = leaf(SchemaType::OneOf, "pick");
  pick.properties = {leaf(SchemaType::Number, "x"), leaf(SchemaType::Number, "y")};
  pick.one_of = {"x", "y"};
  SchemaNode names = leaf(SchemaType::Map, "names");
  names.items = {leaf(SchemaType::Boolean, "")};
  SchemaNode either = leaf(SchemaType::Either, "either");
  either.items = {leaf(SchemaType::String, ""), leaf(SchemaType::Number, "")};
  root.properties = {count, ratio, mode, where, list, pick, names, either};
  return schema;
}

TEST(Schema, ValidDocumentGetsDefaults) {
  const SchemaValidation result = validate_and_complete(small_schema(), json{{"ratio", 0.5}});
  EXPECT_TRUE(result.errors.empty());
  EXPECT_EQ(result.completed.at("count"), 3);
  EXPECT_FALSE(result.completed.contains("mode"));  // optional, no default
}

TEST(Schema, EveryErrorIsReportedWithItsPath) {
  const json document = {{"count", 0},          {"ratio", "nan"},        {"mode", "alpah"},
                         {"where", {0, 0, 0}},  {"list", json::array()}, {"pick", {{"x", 1}, {"y", 2}}},
                         {"names", {{"a", 1}}}, {"either", true},        {"cuont", 1}};
  const SchemaValidation result = validate_and_complete(small_schema(), document);
  const std::vector<std::string> expected = {
      "cuont: unknown key; did you mean \"count\"?",
      "count: must be >= 1, got 0",
      "ratio: must be a number, got \"nan\"",
      "mode: must be one of \"alpha\", \"beta\", got \"alpah\"; did you mean \"alpha\"?",
      "where: must not be the zero vector",
      "list: must hold at least 1 element, got 0",
      "pick: must hold exactly one of \"x\", \"y\"; found \"x\", \"y\"",
      "names.a: must be true or false, got 1",
      "either: must be a string or a number, got true",
  };
  EXPECT_EQ(result.errors, expected);
}

TEST(Schema, MissingRequiredAndWrongRootType) {
  EXPECT_EQ(validate_and_complete(small_schema(), json::object()).errors,
            std::vector<std::string>{"ratio: missing required key (ratio doc)"});
  EXPECT_EQ(validate_and_complete(small_schema(), json::array()).errors,
            std::vector<std::string>{"(scene): must be an object, got []"});
}

TEST(Schema, NumbersRangesAndIntegers) {
  Schema schema = small_schema();
  auto errors = [&](const json& document) { return validate_and_complete(schema, document).errors; };
  EXPECT_TRUE(errors({{"ratio", 1}}).empty());  // inclusive maximum
  EXPECT_EQ(errors({{"ratio", 0}}), std::vector<std::string>{"ratio: must be > 0, got 0"});
  EXPECT_EQ(errors({{"ratio", 1.5}}), std::vector<std::string>{"ratio: must be <= 1, got 1.5"});
  EXPECT_EQ(errors({{"ratio", std::nan("")}}), std::vector<std::string>{"ratio: must be a finite number, got nan"});
  // An integer may be written 4.0 (stored as 4), not 4.5.
  const SchemaValidation four = validate_and_complete(schema, {{"ratio", 1}, {"count", 4.0}});
  EXPECT_TRUE(four.errors.empty());
  EXPECT_TRUE(four.completed.at("count").is_number_integer());
  EXPECT_EQ(errors({{"ratio", 1}, {"count", 4.5}}), std::vector<std::string>{"count: must be an integer, got 4.5"});
  EXPECT_EQ(errors({{"ratio", 1}, {"where", {1, "2", 3}}}),
            std::vector<std::string>{"where: must be an array of 3 numbers [x, y, z], got [1,\"2\",3]"});
  EXPECT_EQ(errors({{"ratio", 1}, {"list", {1, 2, 3}}}),
            std::vector<std::string>{"list: must hold at most 2 elements, got 3"});
}

TEST(Schema, UnknownKeyWithoutCloseMatchListsAllowedKeys) {
  const auto errors = validate_and_complete(small_schema(), {{"ratio", 1}, {"zzzzzz", 1}}).errors;
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0],
            "zzzzzz: unknown key; allowed keys: \"count\", \"ratio\", \"mode\", \"where\", \"list\", \"pick\", "
            "\"names\", \"either\"");
}

TEST(Schema, TaggedObjectsCheckTheKeysOfTheirVariant) {
  Schema schema;
  schema.root.type = SchemaType::Object;
  SchemaNode law = leaf(SchemaType::String, "law");
  law.required = true;
  law.allowed = {"a", "b"};
  schema.root.properties = {law};
  schema.root.tag_key = "law";
  SchemaNode x = leaf(SchemaType::Number, "x");
  x.required = true;
  schema.root.variants = {{"a", "variant a", {x}}, {"b", "variant b", {leaf(SchemaType::Number, "y")}}};

  EXPECT_TRUE(validate_and_complete(schema, {{"law", "a"}, {"x", 1}}).errors.empty());
  EXPECT_EQ(validate_and_complete(schema, {{"law", "a"}, {"x", 1}, {"y", 2}}).errors,
            std::vector<std::string>{"y: unknown key for law \"a\"; allowed keys: \"law\", \"x\""});
  EXPECT_EQ(validate_and_complete(schema, {{"law", "a"}, {"x", 1}, {"lwa", 2}}).errors,
            std::vector<std::string>{"lwa: unknown key for law \"a\"; did you mean \"law\"?"});
  EXPECT_EQ(validate_and_complete(schema, {{"law", "b"}}).errors, std::vector<std::string>{});
  EXPECT_EQ(validate_and_complete(schema, {{"law", "a"}}).errors,
            std::vector<std::string>{"x: missing required key (x doc)"});
  // An unusable tag is reported once; the variants' keys are not reported as unknown.
  EXPECT_EQ(validate_and_complete(schema, {{"law", "c"}, {"x", 1}}).errors,
            std::vector<std::string>{"law: must be one of \"a\", \"b\", got \"c\""});
}

TEST(Schema, RefsResolveThroughDefinitionsRecursively) {
  Schema schema;
  SchemaNode tree = leaf(SchemaType::Object, "");
  SchemaNode children = leaf(SchemaType::Array, "children");
  SchemaNode child = leaf(SchemaType::Ref, "");
  child.ref = "tree";
  children.items = {child};
  tree.properties = {leaf(SchemaType::Number, "value"), children};
  schema.definitions["tree"] = tree;
  schema.root = leaf(SchemaType::Ref, "");
  schema.root.ref = "tree";
  const json document = json::parse(R"({"value": 1, "children": [{"value": 2}, {"children": [{"value": "x"}]}]})");
  EXPECT_EQ(validate_and_complete(schema, document).errors,
            std::vector<std::string>{"children[1].children[0].value: must be a number, got \"x\""});

  const json exported = to_json_schema(schema);
  EXPECT_EQ(exported.at("$ref"), "#/definitions/tree");
  EXPECT_EQ(exported.at("definitions").at("tree").at("properties").at("children").at("items").at("$ref"),
            "#/definitions/tree");
}

TEST(Schema, JsonSchemaExportOfKeysRangesAndOneOf) {
  const json exported = to_json_schema(small_schema());
  EXPECT_EQ(exported.at("$schema"), "http://json-schema.org/draft-07/schema#");
  EXPECT_EQ(exported.at("additionalProperties"), false);
  EXPECT_EQ(exported.at("required"), json::array({"ratio"}));
  const json& properties = exported.at("properties");
  EXPECT_EQ(properties.at("count").at("type"), "integer");
  EXPECT_EQ(properties.at("count").at("minimum"), 1);
  EXPECT_EQ(properties.at("count").at("default"), 3);
  EXPECT_EQ(properties.at("ratio").at("exclusiveMinimum"), 0);
  EXPECT_EQ(properties.at("ratio").at("maximum"), 1);
  EXPECT_EQ(properties.at("mode").at("enum"), json::array({"alpha", "beta"}));
  EXPECT_EQ(properties.at("where").at("minItems"), 3);
  EXPECT_EQ(properties.at("pick").at("oneOf"), json::parse(R"([{"required": ["x"]}, {"required": ["y"]}])"));
  EXPECT_EQ(properties.at("names").at("additionalProperties").at("type"), "boolean");
  EXPECT_EQ(properties.at("either").at("oneOf").size(), 2u);
}

TEST(Schema, MessageHelpers) {
  EXPECT_EQ(format_number(-1), "-1");
  EXPECT_EQ(format_number(0), "0");
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(format_number(1e-6), "1e-06");
  EXPECT_EQ(json_path_key("", "bodies"), "bodies");
  EXPECT_EQ(json_path_key("bodies[0].regions", "muscle"), "bodies[0].regions.muscle");
  EXPECT_EQ(json_path_key("bodies[0].regions", "*"), "bodies[0].regions[\"*\"]");
  EXPECT_EQ(json_path_index("bodies", 2), "bodies[2]");
  EXPECT_EQ(edit_distance("density", "density"), 0u);
  EXPECT_EQ(edit_distance("densty", "density"), 1u);
  EXPECT_EQ(edit_distance("dnesity", "density"), 1u);  // a transposition counts once
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(closest_match("Densiti", {"density", "material"}), std::optional<std::string>("density"));
  EXPECT_EQ(closest_match("xyz", {"density", "material"}), std::nullopt);
}

}  // namespace
}  // namespace sinew::scene
