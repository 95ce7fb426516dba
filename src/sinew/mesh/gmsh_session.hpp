#pragma once
/// @file gmsh_session.hpp
/// Scoped use of Gmsh's C++ API: initialize/finalize, silence, error capture.
///
/// Gmsh is one global, non-thread-safe state. A GmshSession owns it for its lifetime: it holds
/// a process-wide lock, initializes Gmsh without reading configuration files, turns terminal
/// output off and captures Gmsh's log instead. Gmsh reports failures either by throwing
/// std::string or (for errors raised inside its OpenMP meshing loops, where an exception would
/// terminate the process) only by logging them; GmshSession::run turns both into InputError
/// carrying Gmsh's own messages.

#include <exception>
#include <mutex>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "sinew/core/error.hpp"

namespace sinew::mesh {

struct GmshSessionOptions {
  int threads = 1;  ///< Gmsh's OpenMP threads (General.NumThreads, Mesh.MaxNumThreads*D)
};

class GmshSession {
 public:
  /// Starts Gmsh; other threads wanting a session wait until this one ends. Throws
  /// std::logic_error when this thread already holds a session (sessions do not nest) and
  /// sinew::Error when Gmsh cannot start.
  explicit GmshSession(const GmshSessionOptions& options = {});
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  /// Runs `step`, a chain of Gmsh calls, and returns its result. When Gmsh throws, or logs an
  /// error while the step runs, throws InputError("<context>: <Gmsh's error messages>").
  /// sinew errors thrown by the step pass through unchanged.
  template <class Step>
  decltype(auto) run(const std::string& context, Step&& step) {
    const std::size_t log_start = log_size();
    try {
      if constexpr (std::is_void_v<decltype(step())>) {
        std::forward<Step>(step)();
        throw_if_logged_errors(context, log_start);
      } else {
        decltype(auto) result = std::forward<Step>(step)();
        throw_if_logged_errors(context, log_start);
        return result;
      }
    } catch (const sinew::Error&) {
      throw;
    } catch (const std::string& gmsh_message) {
      throw_gmsh_error(context, log_start, gmsh_message);
    } catch (const std::exception& exception) {
      throw_gmsh_error(context, log_start, exception.what());
    } catch (...) {
      throw_gmsh_error(context, log_start, "unknown exception");
    }
  }

  /// Every line Gmsh logged in this session ("Error: ...", "Warning: ...").
  std::vector<std::string> log() const;

 private:
  std::size_t log_size() const;
  void throw_if_logged_errors(const std::string& context, std::size_t log_start) const;
  [[noreturn]] void throw_gmsh_error(const std::string& context, std::size_t log_start,
                                     const std::string& thrown_message) const;

  std::unique_lock<std::mutex> lock_;
};

}  // namespace sinew::mesh
