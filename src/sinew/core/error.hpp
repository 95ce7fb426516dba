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

/// An output file or directory could not be written (full disk, permissions, I/O error).
/// Files written before stay complete: every output is written atomically.
class OutputError : public Error {
 public:
  using Error::Error;
};

/// The machine's memory ran out (an allocation or a sparse factorization failed for memory).
/// Never reported as a numerical failure: halving a step does not make memory appear.
class OutOfMemoryError : public Error {
 public:
  using Error::Error;
};

}  // namespace sinew
