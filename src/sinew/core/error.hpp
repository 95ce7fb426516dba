#pragma once
/// @file error.hpp
/// Exceptions with messages meant for the user: every message says what is wrong, where
/// (file, key path, element), and, when it can, what to do about it.

#include <stdexcept>
#include <string>

namespace sinew {

/// Base of every sinew error.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Bad user input: scene files, meshes, parameters. Reported without a stack of internals.
class InputError : public Error {
 public:
  using Error::Error;
};

/// A numerical failure the caller may recover from (inverted element, no convergence).
class SolveError : public Error {
 public:
  using Error::Error;
};

}  // namespace sinew
