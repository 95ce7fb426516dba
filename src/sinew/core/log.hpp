#pragma once
/// @file log.hpp
/// The project's logger (spdlog). Libraries log at debug/info; the CLI decides the level.

#include <spdlog/spdlog.h>

namespace sinew {

/// The shared logger named "sinew" (created on first use, writes to stderr).
spdlog::logger& logger();

}  // namespace sinew
