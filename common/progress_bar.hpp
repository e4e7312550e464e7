#pragma once
// A simple terminal progress bar on stderr for long work (scans, benchmarks):
//   scan stretch [#########.........] 3/7  elapsed 0:42  ETA 0:56  <note>
// It redraws one line with '\r' and is silent when stderr is not a terminal or when the
// environment variable CI is "true" (logs then stay clean); the caller prints its own summary.
#include <chrono>
#include <string>

namespace mesochain {

class ProgressBar {
 public:
  // `total` steps of work; `label` is printed before the bar.
  ProgressBar(std::string label, int total);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // `done` steps finished (0..total); `note` is shown after the ETA (e.g. the current point).
  // The ETA extrapolates the mean time of the steps finished since construction; steps that
  // were already done at the start (e.g. resumed from a checkpoint) are passed to `skip`.
  void update(int done, const std::string& note = "");
  // Marks `count` steps as done without timing them (resumed work).
  void skip(int count);
  // Ends the line (once); called by the destructor too.
  void finish();

  bool enabled() const { return enabled_; }
  // The bar text for given numbers (no escape codes); public for tests.
  static std::string render(const std::string& label, int done, int total, double elapsedSeconds,
                            double etaSeconds, const std::string& note, int width = 24);
  // "m:ss" or "h:mm:ss"; "--:--" for a negative (unknown) time.
  static std::string formatDuration(double seconds);

 private:
  std::string label_;
  int total_;
  int skipped_ = 0;
  bool enabled_;
  bool finished_ = false;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
};

// True when progress output should be drawn: stderr is a terminal and CI is not "true".
bool progressOutputEnabled();

}  // namespace mesochain
