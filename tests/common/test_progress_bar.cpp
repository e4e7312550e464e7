// The terminal rule of common/progress_bar.hpp: a bar redrawn with '\r' on a terminal, plain
// lines (a line per finished step, or per lineEvery steps, and per stage) otherwise, nothing
// when quiet; -v adds a line per new note.
#include <algorithm>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "common/progress_bar.hpp"

namespace mesochain {
namespace {

int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

TEST(ProgressLines, OneLinePerFinishedStepAndNoCarriageReturn) {
  std::ostringstream out;
  {
    ProgressBar bar("scan stretch", 3, 1, ProgressMode::Lines, out);
    for (int k = 0; k < 3; ++k) {
      bar.update(k, "point " + std::to_string(k + 1));        // starting a point: no line
      bar.update(k, "point " + std::to_string(k + 1) + " evaluation 4");  // notes: no line
      bar.update(k + 1);
    }
  }
  const std::string s = out.str();
  EXPECT_EQ(lines(s), 3) << s;
  EXPECT_EQ(s.find('\r'), std::string::npos);
  EXPECT_NE(s.find("scan stretch: 1/3  elapsed "), std::string::npos) << s;
  EXPECT_NE(s.find("scan stretch: 3/3  elapsed "), std::string::npos) << s;
}

TEST(ProgressLines, EveryTenthAndStagesAndResumedSteps) {
  std::ostringstream out;
  ProgressBar bar("dem", 100, 10, ProgressMode::Lines, out);
  for (int k = 0; k <= 100; ++k) bar.update(k);
  EXPECT_EQ(lines(out.str()), 10) << out.str();  // 10, 20, ..., 100
  std::ostringstream staged;
  ProgressBar sk("skgen", 100, 100, ProgressMode::Lines, staged);
  sk.stage("atom H");
  sk.update(30, "atom H");
  sk.stage("atom H");  // the same stage again: no line
  sk.stage("pair H-H");
  sk.update(100, "pair H-H");
  EXPECT_EQ(staged.str(), "skgen: atom H\nskgen: pair H-H\n" + staged.str().substr(staged.str().find("skgen: 100")));
  EXPECT_EQ(lines(staged.str()), 3);
  // Steps restored from a checkpoint are not announced again.
  std::ostringstream resumed;
  ProgressBar r("scan", 5, 1, ProgressMode::Lines, resumed);
  r.skip(3);
  r.update(3, "point 4");
  r.update(4);
  r.update(5);
  EXPECT_EQ(lines(resumed.str()), 2) << resumed.str();
}

TEST(ProgressLines, BarRedrawsAndSilentWritesNothing) {
  std::ostringstream bar, silent;
  {
    ProgressBar b("x", 2, 1, ProgressMode::Bar, bar);
    b.update(1, "half");
    b.update(2);
  }
  const std::string drawn = bar.str();
  EXPECT_EQ(std::count(drawn.begin(), drawn.end(), '\r'), 2);
  EXPECT_EQ(lines(drawn), 1);  // the line ended once at finish
  {
    ProgressBar q("x", 2, 1, ProgressMode::Silent, silent);
    q.stage("s");
    q.update(1, "half");
    q.update(2);
  }
  EXPECT_EQ(silent.str(), "");
}

TEST(ProgressLines, VerbosityChoosesTheMode) {
  setVerbosity(Verbosity::Quiet);
  EXPECT_EQ(progressMode(), ProgressMode::Silent);
  setVerbosity(Verbosity::Verbose);
  EXPECT_EQ(progressMode(), ProgressMode::Lines);
  std::ostringstream out;
  {
    ProgressBar b("scan", 2, 1, ProgressMode::Lines, out);
    b.update(0, "evaluation 1");
    b.update(0, "evaluation 2");
    b.update(1);
  }
  EXPECT_EQ(lines(out.str()), 3) << out.str();  // -v: every new note, then the step
  setVerbosity(Verbosity::Normal);
  // Off a terminal (as under ctest) plain lines, else the bar.
  if (!isatty(STDERR_FILENO)) {
    EXPECT_EQ(progressMode(), ProgressMode::Lines);
  }
}

}  // namespace
}  // namespace mesochain
