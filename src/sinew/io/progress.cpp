#include "sinew/io/progress.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sinew/core/error.hpp"

namespace sinew::io {

namespace {

/// The file descriptor behind one of the standard streams, or -1 for any other stream.
int standard_stream_descriptor(const std::ostream* stream) {
  if (stream == &std::cerr || stream == &std::clog) return STDERR_FILENO;
  if (stream == &std::cout) return STDOUT_FILENO;
  return -1;
}

/// Columns of the terminal on `descriptor`, 0 if unknown.
int terminal_columns(int descriptor) {
  winsize size{};
  if (descriptor >= 0 && ::ioctl(descriptor, TIOCGWINSZ, &size) == 0) return size.ws_col;
  return 0;
}

}  // namespace

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) return "--:--";
  const auto total = static_cast<long long>(std::llround(seconds));
  const long long hours = total / 3600;
  const long long minutes = (total / 60) % 60;
  const long long secs = total % 60;
  char buffer[48];
  if (hours > 0) {
    std::snprintf(buffer, sizeof(buffer), "%lld:%02lld:%02lld", hours, minutes, secs);
  } else {
    std::snprintf(buffer, sizeof(buffer), "%lld:%02lld", minutes, secs);
  }
  return buffer;
}

ProgressBar::ProgressBar(ProgressBarOptions options) : options_(std::move(options)) {
  if (!(options_.total > 0.0) || !std::isfinite(options_.total)) {
    throw Error("progress bar '" + options_.label + "': the total amount of work must be positive and finite");
  }
  options_.bar_width = std::max(options_.bar_width, 1);
  const int descriptor = standard_stream_descriptor(options_.stream);
  const bool is_terminal = descriptor >= 0 && ::isatty(descriptor) == 1;
  enabled_ = options_.stream != nullptr && (options_.force_enabled || is_terminal);
  if (is_terminal) terminal_columns_ = terminal_columns(descriptor);
  start_ = Clock::now();
  last_draw_ = start_;
}

ProgressBar::~ProgressBar() {
  if (drawn_ && !finished_) finish();
}

void ProgressBar::update(double done, std::string_view status_text) {
  if (!enabled_ || finished_) return;
  done_ = std::isfinite(done) ? std::clamp(done, 0.0, options_.total) : done_;
  status_.assign(status_text);
  const Clock::time_point now = Clock::now();
  const double since_last_draw = std::chrono::duration<double>(now - last_draw_).count();
  if (!drawn_ || done_ >= options_.total || since_last_draw >= options_.min_redraw_interval_seconds) {
    draw(now);
  }
}

void ProgressBar::finish(std::string_view status_text) {
  if (!enabled_ || finished_) return;
  if (!status_text.empty()) status_.assign(status_text);
  draw(Clock::now());
  *options_.stream << '\n' << std::flush;
  finished_ = true;
}

void ProgressBar::draw(Clock::time_point now) {
  const double fraction = done_ / options_.total;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double remaining = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : -1.0;

  const auto filled = static_cast<int>(std::floor(fraction * options_.bar_width));
  std::string line;
  if (!options_.label.empty()) {
    line += options_.label;
    line += ' ';
  }
  line += '[';
  line.append(static_cast<std::size_t>(filled), '#');
  line.append(static_cast<std::size_t>(options_.bar_width - filled), '.');
  line += ']';
  char percent[16];
  std::snprintf(percent, sizeof(percent), " %5.1f%%", 100.0 * fraction);
  line += percent;
  line += "  elapsed " + format_duration(elapsed);
  line += "  ETA " + format_duration(remaining);
  if (!status_.empty()) {
    line += "  ";
    for (const char c : status_) line += (c == '\n' || c == '\r') ? ' ' : c;
  }
  // A line wider than the terminal would wrap, and '\r' would then redraw only its tail.
  if (terminal_columns_ > 1 && line.size() >= static_cast<std::size_t>(terminal_columns_)) {
    line.resize(static_cast<std::size_t>(terminal_columns_ - 1));
  }
  const std::size_t length = line.size();
  if (length < last_line_length_) line.append(last_line_length_ - length, ' ');  // erase leftovers
  last_line_length_ = length;

  *options_.stream << '\r' << line << std::flush;
  drawn_ = true;
  last_draw_ = now;
}

}  // namespace sinew::io
