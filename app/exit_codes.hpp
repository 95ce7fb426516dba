#pragma once
/// @file exit_codes.hpp
/// The exit codes of `sinew`, each with the one line `sinew --help` and the README show.

#include <array>
#include <string>

namespace sinew::app {

enum class ExitCode : int {
  Success = 0,
  InputRejected = 1,  ///< bad scene, mesh or command line; nothing written
  SolveStopped = 2,   ///< the solve could not go on; outputs so far and last_converged.vtu kept
  OutputFailed = 3,   ///< an output could not be written (full disk, permissions)
  OutOfMemory = 4,    ///< memory ran out
  InternalError = 5,  ///< a defect of sinew itself
  Interrupted = 6,    ///< SIGINT or SIGTERM; checkpoint of the last converged state written
};

struct ExitCodeDoc {
  ExitCode code;
  const char* meaning;
};

inline constexpr std::array<ExitCodeDoc, 7> kExitCodeDocs{{
    {ExitCode::Success, "done: the run solved to its end (validate: the scene is valid)"},
    {ExitCode::InputRejected,
     "the scene, a mesh, the output directory or the command line was rejected; nothing was written"},
    {ExitCode::SolveStopped,
     "the solve stopped before the end; outputs so far, last_converged.vtu and summary.json are kept"},
    {ExitCode::OutputFailed,
     "an output could not be written (full disk, permissions); files written before are complete, summary.json "
     "says where the run stopped if it could be written"},
    {ExitCode::OutOfMemory, "memory ran out; outputs so far are complete, summary.json says where"},
    {ExitCode::InternalError, "an internal error of sinew (please report it with the scene)"},
    {ExitCode::Interrupted,
     "interrupted (SIGINT, SIGTERM): the last converged state is in checkpoint.cbor and last_converged.vtu; "
     "go on with the same command and --resume"},
}};

/// "Exit codes:\n  0  done: ...\n  1  ..." for the help text.
inline std::string exit_codes_help() {
  std::string text = "Exit codes:\n";
  for (const auto& doc : kExitCodeDocs)
    text += "  " + std::to_string(static_cast<int>(doc.code)) + "  " + doc.meaning + "\n";
  return text;
}

}  // namespace sinew::app
