#pragma once
/// @file parameter_checks.hpp
/// Range checks shared by the laws' validate() functions. Each throws sinew::InputError with
/// a message naming the law, the parameter and the offending value, e.g.
/// "mooney-rivlin: C1 must be > 0, got -1".

#include <string_view>

namespace sinew::material {

/// Throws unless value is finite (not NaN, not +-inf).
void require_finite(std::string_view law, std::string_view parameter, double value);
/// Throws unless value is finite and > 0.
void require_positive(std::string_view law, std::string_view parameter, double value);
/// Throws unless value is finite and >= 0.
void require_non_negative(std::string_view law, std::string_view parameter, double value);

/// Throws unless the small-strain moduli of a parameter set are finite and > 0 (rejects laws
/// that are unstable at rest, and parameters so large that the moduli overflow). Each
/// `formula` spells how that modulus follows from the parameters, e.g.
/// "4 a + 4 alpha beta^2 - 4/3 alpha beta"; `hint`, when not empty, is appended to the
/// message of a non-positive modulus (what to change).
void require_positive_initial_moduli(std::string_view law, double shear_modulus,
                                     std::string_view shear_formula, double bulk_modulus,
                                     std::string_view bulk_formula, std::string_view hint = {});

}  // namespace sinew::material
