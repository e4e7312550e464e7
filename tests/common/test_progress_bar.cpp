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

// A long step (a scan point relaxed for an hour) shows its note once no line was written for
// the heartbeat: with a heartbeat of 0 every new note is a line, a repeated note is not; with the
// default (5 minutes) a quick step's notes stay silent, as in the first test.
TEST(ProgressLines, HeartbeatShowsTheNoteOfALongStep) {
  std::ostringstream out;
  ProgressBar bar("scan stretch", 2, 1, ProgressMode::Lines, out);
  bar.setHeartbeat(0.0);
  bar.update(0, "point 1/2: evaluation 1 max|force| 3.0e-02");
  bar.update(0, "point 1/2: evaluation 1 max|force| 3.0e-02");  // the same note: no line
  bar.update(0, "point 1/2: evaluation 2 max|force| 9.0e-03");
  EXPECT_EQ(lines(out.str()), 2) << out.str();
  EXPECT_NE(out.str().find("scan stretch: 0/2  elapsed 0:00  ETA --:--  point 1/2: evaluation 2 max|force| 9.0e-03\n"),
            std::string::npos)
      << out.str();
  std::ostringstream quick;
  ProgressBar q("scan stretch", 2, 1, ProgressMode::Lines, quick);
  EXPECT_EQ(ProgressBar::kDefaultHeartbeatSeconds, 300.0);
  for (int k = 1; k <= 50; ++k) q.update(0, "point 1/2: evaluation " + std::to_string(k));
  EXPECT_EQ(quick.str(), "");
  std::ostringstream silent;
  ProgressBar s("scan stretch", 2, 1, ProgressMode::Silent, silent);
  s.setHeartbeat(0.0);
  s.update(0, "point 1/2: evaluation 1");
  EXPECT_EQ(silent.str(), "");
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
