#pragma once
/// @file law.hpp
/// The hyperelastic laws sinew implements (docs/theory.md) and their names, as scene files
/// ("law") and messages write them.

#include "sinew/core/enum_names.hpp"

namespace sinew::material {

/// A base strain-energy function (the order of BaseLawParams' alternatives).
enum class Law { MooneyRivlin, VerondaWestmann, NeoHookean };

/// Scene names of Law.
inline constexpr NameTable<Law, 3> kLawNames{{
    {Law::MooneyRivlin, "mooney-rivlin"},
    {Law::VerondaWestmann, "veronda-westmann"},
    {Law::NeoHookean, "neo-hookean"},
}};
constexpr const auto& enum_names(Law) { return kLawNames; }

}  // namespace sinew::material
