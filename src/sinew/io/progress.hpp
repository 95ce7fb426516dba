#pragma once
/// @file progress.hpp
/// A one-line terminal progress bar for long runs:
///   `label [##########..........]  50.0%  elapsed 0:12  ETA 0:12  increment 12/50  newton 3`
/// It draws only when its stream is a terminal (or when forced), so logs and redirected
/// output stay clean; otherwise every call does nothing.

#include <chrono>
#include <cstddef>
#include <iostream>
#include <string>
#include <string_view>

namespace sinew::io {

struct ProgressBarOptions {
  /// Total amount of work, in the caller's unit (increments, simulated seconds, ...); > 0.
  double total = 1.0;
  /// Shown before the bar, e.g. "loading".
  std::string label;
  /// Where the bar is drawn; must outlive the ProgressBar.
  std::ostream* stream = &std::cerr;
  /// Draw even when `stream` is not a terminal (tests, or a caller that knows better).
  bool force_enabled = false;
  /// Width of the bar itself, in characters.
  int bar_width = 30;
  /// Minimum time between two redraws, in seconds (~10 redraws/s by default). Reaching the
  /// total always redraws.
  double min_redraw_interval_seconds = 0.1;
};

/// Redraws one line in place ('\r'). Not thread-safe: update it from one thread. Anything
/// else written to the same stream while the bar is shown should start with a new line.
class ProgressBar {
 public:
  explicit ProgressBar(ProgressBarOptions options);
  /// Calls finish() if the bar was drawn and not finished, so the terminal's next line is clean.
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// Reports `done` units of work out of the total (clamped to [0, total]) with a status
  /// text such as "increment 12/50  newton 3  |r|=1.2e-7". Redraws at most every
  /// `min_redraw_interval_seconds`.
  void update(double done, std::string_view status_text = {});
  /// Draws the last state (with `status_text` if given) and ends the line. Later calls do nothing.
  void finish(std::string_view status_text = {});

  /// True if the bar draws anything (the stream is a terminal, or forced).
  bool enabled() const { return enabled_; }

 private:
  using Clock = std::chrono::steady_clock;

  void draw(Clock::time_point now);

  ProgressBarOptions options_;
  bool enabled_ = false;
  bool finished_ = false;
  bool drawn_ = false;
  int terminal_columns_ = 0;  ///< 0 when unknown (not a terminal): no truncation
  Clock::time_point start_;
  Clock::time_point last_draw_;
  double done_ = 0.0;
  std::string status_;
  std::size_t last_line_length_ = 0;
};

/// "m:ss" below an hour, "h:mm:ss" above; "--:--" for a negative or non-finite duration.
std::string format_duration(double seconds);

}  // namespace sinew::io
