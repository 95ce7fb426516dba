#include "sinew/io/progress.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "sinew/core/error.hpp"

namespace sinew::io {
namespace {

ProgressBarOptions forced_into(std::ostringstream& out) {
  ProgressBarOptions options;
  options.total = 50.0;
  options.label = "loading";
  options.stream = &out;
  options.force_enabled = true;
  options.min_redraw_interval_seconds = 0.0;  // draw on every update
  return options;
}

TEST(ProgressBar, ForcedBarShowsLabelPercentageTimesAndStatus) {
  std::ostringstream out;
  ProgressBar bar(forced_into(out));
  EXPECT_TRUE(bar.enabled());
  bar.update(12.0, "increment 12/50  newton 3  |r|=1.2e-7");
  const std::string line = out.str();
  EXPECT_EQ(line.front(), '\r');
  EXPECT_NE(line.find("loading"), std::string::npos) << line;
  EXPECT_NE(line.find("24.0%"), std::string::npos) << line;
  EXPECT_NE(line.find("increment 12/50  newton 3  |r|=1.2e-7"), std::string::npos) << line;
  EXPECT_NE(line.find("elapsed "), std::string::npos) << line;
  EXPECT_NE(line.find("ETA "), std::string::npos) << line;
  EXPECT_NE(line.find('['), std::string::npos) << line;
  EXPECT_EQ(line.find('\n'), std::string::npos) << "the bar must stay on one line";
}

TEST(ProgressBar, FinishShowsCompletionAndEndsTheLine) {
  std::ostringstream out;
  ProgressBar bar(forced_into(out));
  bar.update(50.0, "done");
  bar.finish("converged");
  const std::string text = out.str();
  EXPECT_NE(text.find("100.0%"), std::string::npos) << text;
  EXPECT_NE(text.find("converged"), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n');
  const std::size_t size_after_finish = text.size();
  bar.update(10.0, "ignored");
  bar.finish();
  EXPECT_EQ(out.str().size(), size_after_finish);
}

TEST(ProgressBar, ShorterLinesEraseTheLongerPreviousLine) {
  std::ostringstream out;
  ProgressBar bar(forced_into(out));
  bar.update(1.0, "a very long status text that will be replaced");
  const std::size_t first_length = out.str().size();
  bar.update(2.0, "short");
  const std::string second = out.str().substr(first_length);
  EXPECT_EQ(second.size(), first_length);  // same width: padded with spaces
  EXPECT_NE(second.find("short"), std::string::npos);
}

TEST(ProgressBar, ProgressIsClampedAndNewlinesInStatusAreFlattened) {
  std::ostringstream out;
  ProgressBar bar(forced_into(out));
  bar.update(-5.0, "two\nlines");
  EXPECT_NE(out.str().find("  0.0%"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("two lines"), std::string::npos) << out.str();
  bar.update(80.0);
  EXPECT_NE(out.str().find("100.0%"), std::string::npos) << out.str();
}

TEST(ProgressBar, RedrawsAreThrottledButCompletionAlwaysDraws) {
  std::ostringstream out;
  ProgressBarOptions options = forced_into(out);
  options.min_redraw_interval_seconds = 1e9;  // never redraws on time alone
  ProgressBar bar(options);
  bar.update(1.0, "first");
  bar.update(2.0, "second");
  bar.update(3.0, "third");
  EXPECT_NE(out.str().find("first"), std::string::npos);
  EXPECT_EQ(out.str().find("second"), std::string::npos);
  EXPECT_EQ(out.str().find("third"), std::string::npos);
  bar.update(50.0, "complete");
  EXPECT_NE(out.str().find("complete"), std::string::npos);
}

TEST(ProgressBar, NonTerminalStreamWritesNothing) {
  std::ostringstream out;
  ProgressBarOptions options = forced_into(out);
  options.force_enabled = false;  // an ostringstream is never a terminal
  {
    ProgressBar bar(options);
    EXPECT_FALSE(bar.enabled());
    bar.update(10.0, "increment 10/50");
    bar.update(50.0, "done");
    bar.finish("converged");
  }
  EXPECT_TRUE(out.str().empty());
}

TEST(ProgressBar, DestructorEndsAnUnfinishedLine) {
  std::ostringstream out;
  {
    ProgressBar bar(forced_into(out));
    bar.update(5.0, "interrupted");
  }
  EXPECT_EQ(out.str().back(), '\n');
}

TEST(ProgressBar, TotalMustBePositive) {
  ProgressBarOptions options;
  options.total = 0.0;
  EXPECT_THROW(ProgressBar{options}, Error);
  options.total = -1.0;
  EXPECT_THROW(ProgressBar{options}, Error);
}

TEST(FormatDuration, MinutesSecondsAndHours) {
  EXPECT_EQ(format_duration(0.0), "0:00");
  EXPECT_EQ(format_duration(59.4), "0:59");
  EXPECT_EQ(format_duration(61.0), "1:01");
  EXPECT_EQ(format_duration(3600.0 + 2 * 60 + 3), "1:02:03");
  EXPECT_EQ(format_duration(-1.0), "--:--");
}

}  // namespace
}  // namespace sinew::io
