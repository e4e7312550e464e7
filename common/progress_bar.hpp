#pragma once
// Progress of long work (scans, skgen, mDEM runs, benchmarks) on stderr, by one terminal rule:
//  - on a terminal: one bar redrawn with '\r'
//      scan stretch [#########.........] 3/7  elapsed 0:42  ETA 0:56  <note>
//  - not on a terminal (a log file, a pipe, or CI=true): a plain line per finished step (per
//    scan point; per tenth of an mDEM run) and per stage, never a '\r':
//      scan stretch: 3/7  elapsed 0:42  ETA 0:56
//    A step that takes long (a scan point relaxed for an hour, a tenth of a 40-hour mDEM run)
//    gets a line with its current note every `heartbeat` seconds (default 300), so that a log
//    of a background run shows it alive and where it is:
//      scan stretch: 0/7  elapsed 1:05:12  ETA --:--  point 1/7: evaluation 95 max|force| 4.2e-04
//  - `mesochain -q`: nothing; `mesochain -v`: plain lines on a terminal too, and every note
//    (e.g. each relaxation step of a scan point).
// The caller prints its own summary.
#include <chrono>
#include <iosfwd>
#include <string>

namespace mesochain {

// Set once by main from -q / -v.
enum class Verbosity { Quiet, Normal, Verbose };
void setVerbosity(Verbosity v);
Verbosity verbosity();

enum class ProgressMode { Silent, Bar, Lines };
// The mode the rule above gives for this process (verbosity, stderr a terminal, CI).
ProgressMode progressMode();

class ProgressBar {
 public:
  // `total` steps of work; `label` is printed before the bar. In Lines mode a line is written
  // each time `done` reaches a further multiple of `lineEvery` steps (and at the end).
  ProgressBar(std::string label, int total, int lineEvery = 1);
  // With an explicit mode and output stream (tests).
  ProgressBar(std::string label, int total, int lineEvery, ProgressMode mode, std::ostream& out);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // `done` steps finished (0..total); `note` is shown after the ETA (e.g. the current point).
  // The ETA extrapolates the mean time of the steps finished since construction; steps that
  // were already done at the start (e.g. resumed from a checkpoint) are passed to `skip`.
  void update(int done, const std::string& note = "");
  // A new stage of the work begins (e.g. "H-C integrals"): a line of its own in Lines mode,
  // the note of the bar otherwise.
  void stage(const std::string& name);
  // Marks `count` steps as done without timing them (resumed work).
  void skip(int count);
  // Lines mode: the longest time without a line while notes arrive (seconds; 0 = a line per note).
  void setHeartbeat(double seconds) { heartbeatSeconds_ = seconds; }
  static constexpr double kDefaultHeartbeatSeconds = 300.0;
  // Ends the line (once); called by the destructor too.
  void finish();

  bool enabled() const { return mode_ == ProgressMode::Bar; }
  ProgressMode mode() const { return mode_; }
  // The bar text for given numbers (no escape codes); public for tests.
  static std::string render(const std::string& label, int done, int total, double elapsedSeconds,
                            double etaSeconds, const std::string& note, int width = 24);
  // The plain line of Lines mode: "label: done/total  elapsed m:ss  ETA m:ss  note".
  static std::string renderLine(const std::string& label, int done, int total, double elapsedSeconds,
                                double etaSeconds, const std::string& note);
  // "m:ss" or "h:mm:ss"; "--:--" for a negative (unknown) time.
  static std::string formatDuration(double seconds);

 private:
  std::string label_;
  int total_;
  int lineEvery_;
  int skipped_ = 0;
  int lastLineDone_ = -1;
  std::string lastNote_, stage_;
  ProgressMode mode_;
  std::ostream* out_;
  bool finished_ = false;
  bool drawn_ = false;
  double heartbeatSeconds_ = kDefaultHeartbeatSeconds;
  std::chrono::steady_clock::time_point start_, lastLine_;
};

// True when the bar is drawn (ProgressMode::Bar).
bool progressOutputEnabled();

}  // namespace mesochain
