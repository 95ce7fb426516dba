/// @file test_enum_names.cpp
/// The generic name-table helpers (sinew/core/enum_names.hpp) on an enum of the test's own.

#include <gtest/gtest.h>

#include "sinew/core/enum_names.hpp"

namespace sinew::test_enum_names {

enum class Fruit { Apple, Pear, Plum };

inline constexpr NameTable<Fruit, 3> kFruitNames{{
    {Fruit::Apple, "apple"},
    {Fruit::Pear, "pear"},
    {Fruit::Plum, "plum"},
}};
constexpr const auto& enum_names(Fruit) { return kFruitNames; }

static_assert(NamedEnum<Fruit>);
static_assert(name_of(Fruit::Pear) == "pear");
static_assert(parse_name<Fruit>("plum") == Fruit::Plum);

namespace {

TEST(EnumNames, NamesRoundTrip) {
  for (const auto& [value, name] : kFruitNames) {
    EXPECT_EQ(name_of(value), name);
    EXPECT_EQ(parse_name<Fruit>(name), value);
  }
}

TEST(EnumNames, UnknownNamesAndValues) {
  EXPECT_FALSE(parse_name<Fruit>("Apple").has_value());  // exact, case-sensitive
  EXPECT_FALSE(parse_name<Fruit>("").has_value());
  EXPECT_FALSE(parse_name<Fruit>("apple ").has_value());
  EXPECT_EQ(name_of(static_cast<Fruit>(7)), "?");
}

TEST(EnumNames, ListsForSchemasAndMessages) {
  EXPECT_EQ(names_of<Fruit>(), (std::vector<std::string>{"apple", "pear", "plum"}));
  EXPECT_EQ(names_list<Fruit>(), "\"apple\", \"pear\", \"plum\"");
}

TEST(EnumNames, NamesAreNulTerminated) {
  // Materials and linear solvers return name_of(...).data() as a C string.
  EXPECT_STREQ(name_of(Fruit::Apple).data(), "apple");
}

}  // namespace
}  // namespace sinew::test_enum_names
