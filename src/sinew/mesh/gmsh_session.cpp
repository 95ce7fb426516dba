#include "sinew/mesh/gmsh_session.hpp"

#include <gmsh.h>

#include <algorithm>
#include <stdexcept>

#include "sinew/core/log.hpp"

namespace sinew::mesh {

namespace {

std::mutex& gmsh_mutex() {
  static std::mutex mutex;
  return mutex;
}

thread_local bool this_thread_holds_session = false;

bool is_error_line(const std::string& line) { return line.rfind("Error", 0) == 0; }

/// OpenCASCADE's confusion tolerance (Precision::Confusion()), which Gmsh's OCC kernel uses:
/// shapes or features smaller than this are degenerate to it.
constexpr const char* kOccTolerance = "1e-7";

/// Gmsh's message, or an explanation when it says nothing.
std::string explained(std::string message) {
  while (!message.empty() && (message.back() == ' ' || message.back() == '\t')) message.pop_back();
  if (message == "OpenCASCADE exception") {
    // OpenCASCADE threw without a message (Standard_Failure with an empty string), e.g. when
    // a box is thinner than its tolerance.
    return std::string("OpenCASCADE failed without a message: the geometry is degenerate, or "
                       "smaller or thinner than OpenCASCADE's tolerance (") +
           kOccTolerance + ") in some direction; check its dimensions";
  }
  if (message.empty()) return "Gmsh reported an error without a message";
  return message;
}

/// "Error: foo" -> "foo", explained.
std::string without_level(const std::string& line) {
  const auto colon = line.find(": ");
  return explained(colon == std::string::npos ? line : line.substr(colon + 2));
}

/// Joins distinct messages with "; ", at most `max_count` of them.
std::string join_distinct(const std::vector<std::string>& messages, std::size_t max_count) {
  std::vector<std::string> kept;
  for (const auto& message : messages) {
    if (std::find(kept.begin(), kept.end(), message) == kept.end()) kept.push_back(message);
  }
  std::string joined;
  for (std::size_t i = 0; i < kept.size() && i < max_count; ++i) {
    joined += (i ? "; " : "") + kept[i];
  }
  if (kept.size() > max_count) joined += "; ...";
  return joined;
}

}  // namespace

GmshSession::GmshSession(const GmshSessionOptions& options) {
  if (this_thread_holds_session) {
    throw std::logic_error("GmshSession: this thread already holds a Gmsh session");
  }
  lock_ = std::unique_lock<std::mutex>(gmsh_mutex());
  try {
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 2);  // errors and warnings reach the log
    // 1 = stop meshing at the first error without throwing: Gmsh's default for the API (2,
    // throw) would throw out of its OpenMP loops and terminate the process.
    gmsh::option::setNumber("General.AbortOnError", 1);
    gmsh::option::setNumber("General.NumThreads", options.threads);
    gmsh::option::setNumber("Mesh.MaxNumThreads1D", options.threads);
    gmsh::option::setNumber("Mesh.MaxNumThreads2D", options.threads);
    gmsh::option::setNumber("Mesh.MaxNumThreads3D", options.threads);
    gmsh::logger::start();
  } catch (const std::string& message) {
    try {
      gmsh::finalize();
    } catch (...) {  // already failing; report the first problem
    }
    throw Error("cannot start Gmsh: " + message);
  }
  this_thread_holds_session = true;
}

GmshSession::~GmshSession() {
  try {
    for (const auto& line : log()) logger().debug("gmsh: {}", line);
    gmsh::logger::stop();
    gmsh::finalize();
  } catch (...) {  // NOLINT(bugprone-empty-catch): nothing sensible to do while unwinding
  }
  this_thread_holds_session = false;
}

std::vector<std::string> GmshSession::log() const {
  std::vector<std::string> lines;
  gmsh::logger::get(lines);
  return lines;
}

std::size_t GmshSession::log_size() const { return log().size(); }

void GmshSession::throw_if_logged_errors(const std::string& context, std::size_t log_start) const {
  const auto lines = log();
  if (std::any_of(lines.begin() + static_cast<std::ptrdiff_t>(std::min(log_start, lines.size())),
                  lines.end(), is_error_line)) {
    throw_gmsh_error(context, log_start, "");
  }
}

void GmshSession::throw_gmsh_error(const std::string& context, std::size_t log_start,
                                   const std::string& thrown_message) const {
  std::vector<std::string> messages;
  try {
    const auto lines = log();
    for (std::size_t i = std::min(log_start, lines.size()); i < lines.size(); ++i) {
      if (is_error_line(lines[i])) messages.push_back(without_level(lines[i]));
    }
  } catch (...) {  // the log is a courtesy; the thrown message still gets reported
  }
  if (!thrown_message.empty()) messages.push_back(explained(thrown_message));
  if (messages.empty()) messages.push_back("Gmsh failed without a message");
  throw InputError(context + ": " + join_distinct(messages, 4));
}

}  // namespace sinew::mesh
