#include "reebkit/collection/progress.h"

#include <gtest/gtest.h>

#include <sstream>

namespace reebkit::test {
namespace {

ProgressState state(std::int64_t ok, std::int64_t failed, std::int64_t skipped, double seconds) {
  ProgressState s;
  s.total = 100;
  s.ok = ok;
  s.failed = failed;
  s.skipped = skipped;
  s.seconds = seconds;
  return s;
}

TEST(Progress, RateAndEtaCountOnlyComputedItems) {
  const ProgressState s = state(18, 2, 30, 4.0);
  EXPECT_DOUBLE_EQ(s.rate(), 5.0);           // 20 computed in 4 s
  EXPECT_DOUBLE_EQ(s.eta(), 50.0 / 5.0);     // 50 left
  EXPECT_LT(state(0, 0, 10, 1.0).eta(), 0);  // nothing computed yet: unknown
  EXPECT_EQ(state(100, 0, 0, 1.0).eta(), 0);
}

TEST(Progress, PlainLinesAtMostEveryIntervalAndAtTheEnd) {
  std::ostringstream out;
  ProgressBar bar(out, false, 10.0);
  for (int k = 1; k <= 100; ++k) bar(state(k, 0, 0, 0.25 * k));  // 25 s in all
  // At 0.25 s, 10.25 s, 20.25 s and the last item.
  std::istringstream lines(out.str());
  std::vector<std::string> got;
  for (std::string line; std::getline(lines, line);) got.push_back(line);
  ASSERT_EQ(got.size(), 4u) << out.str();
  EXPECT_EQ(got[0].rfind("indexed 1/100  4.0 meshes/s  ETA 25 s", 0), 0u) << got[0];
  EXPECT_EQ(got[3].rfind("indexed 100/100", 0), 0u) << got[3];
  EXPECT_EQ(out.str().find('\r'), std::string::npos);
}

TEST(Progress, TerminalRedrawsOneLineInPlace) {
  std::ostringstream out;
  ProgressBar bar(out, true);
  bar(state(50, 1, 0, 51.0));
  EXPECT_EQ(out.str(), "\r[###############...............] 51/100  1.0 meshes/s  ETA 49 s  1 failed\033[K");
  bar(state(51, 1, 0, 51.05));  // within 0.1 s: not redrawn
  EXPECT_EQ(out.str().find("52/100"), std::string::npos);
  out.str("");
  bar.finish(state(97, 3, 0, 125.0));
  EXPECT_EQ(out.str(), "\r\033[K100 meshes: 97 ok, 3 failed, 0 already indexed, in 125.00 s (0.8 meshes/s)\n");
}

TEST(Progress, TheVerbAndUnitAreTheCommandsOwn) {
  std::ostringstream out;
  ProgressBar bar(out, false, 10.0, "matched", "pairs");
  ProgressState s;
  s.total = 79800;
  s.ok = 39900;
  s.seconds = 2.0;
  bar(s);
  EXPECT_EQ(out.str(), "matched 39900/79800  19950.0 pairs/s  ETA 2 s\n");
  bar.clear();  // nothing drawn in place
  EXPECT_EQ(out.str(), "matched 39900/79800  19950.0 pairs/s  ETA 2 s\n");
  std::ostringstream terminal;
  ProgressBar in_place(terminal, true, 10.0, "matched", "pairs");
  in_place.clear();
  EXPECT_EQ(terminal.str(), "\r\033[K");
}

}  // namespace
}  // namespace reebkit::test
