/// @file parameter_checks.cpp

#include "sinew/material/parameter_checks.hpp"

#include <cmath>

#include <fmt/format.h>

#include "sinew/core/error.hpp"

namespace sinew::material {

void require_finite(std::string_view law, std::string_view parameter, double value) {
  if (!std::isfinite(value)) {
    throw InputError(fmt::format("{}: {} must be a finite number, got {}", law, parameter, value));
  }
}

void require_positive(std::string_view law, std::string_view parameter, double value) {
  require_finite(law, parameter, value);
  if (!(value > 0.0)) {
    throw InputError(fmt::format("{}: {} must be > 0, got {}", law, parameter, value));
  }
}

void require_non_negative(std::string_view law, std::string_view parameter, double value) {
  require_finite(law, parameter, value);
  if (!(value >= 0.0)) {
    throw InputError(fmt::format("{}: {} must be >= 0, got {}", law, parameter, value));
  }
}

namespace {
void require_positive_modulus(std::string_view law, std::string_view which, double modulus,
                              std::string_view formula, std::string_view hint) {
  if (!std::isfinite(modulus)) {
    throw InputError(fmt::format("{}: the initial {} modulus {} must be finite, got {}; the "
                                 "parameters are too large",
                                 law, which, formula, modulus));
  }
  if (!(modulus > 0.0)) {
    throw InputError(fmt::format(
        "{}: the initial {} modulus {} must be > 0, got {}; the law would be unstable at rest "
        "with these parameters{}{}",
        law, which, formula, modulus, hint.empty() ? "" : ": ", hint));
  }
}
}  // namespace

void require_positive_initial_moduli(std::string_view law, double shear_modulus,
                                     std::string_view shear_formula, double bulk_modulus,
                                     std::string_view bulk_formula, std::string_view hint) {
  require_positive_modulus(law, "shear", shear_modulus, shear_formula, hint);
  require_positive_modulus(law, "bulk", bulk_modulus, bulk_formula, hint);
}

}  // namespace sinew::material
