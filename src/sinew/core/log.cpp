#include "sinew/core/log.hpp"

#include <spdlog/sinks/stdout_color_sinks.h>

namespace sinew {

spdlog::logger& logger() {
  static std::shared_ptr<spdlog::logger> instance = [] {
    auto existing = spdlog::get("sinew");
    if (existing) return existing;
    auto created = spdlog::stderr_color_mt("sinew");
    created->set_pattern("%^[%l]%$ %v");
    created->set_level(spdlog::level::info);
    return created;
  }();
  return *instance;
}

}  // namespace sinew
