#include "common/progress_bar.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>

#include <fmt/format.h>
#include <unistd.h>

namespace mesochain {

namespace {
Verbosity& verbosityFlag() {
  static Verbosity v = Verbosity::Normal;
  return v;
}
}  // namespace

void setVerbosity(Verbosity v) { verbosityFlag() = v; }
Verbosity verbosity() { return verbosityFlag(); }

ProgressMode progressMode() {
  if (verbosity() == Verbosity::Quiet) return ProgressMode::Silent;
  if (verbosity() == Verbosity::Verbose) return ProgressMode::Lines;
  const char* ci = std::getenv("CI");
  if (ci && std::strcmp(ci, "true") == 0) return ProgressMode::Lines;
  return isatty(STDERR_FILENO) != 0 ? ProgressMode::Bar : ProgressMode::Lines;
}

bool progressOutputEnabled() { return progressMode() == ProgressMode::Bar; }

ProgressBar::ProgressBar(std::string label, int total, int lineEvery)
    : ProgressBar(std::move(label), total, lineEvery, progressMode(), std::cerr) {}

ProgressBar::ProgressBar(std::string label, int total, int lineEvery, ProgressMode mode, std::ostream& out)
    : label_(std::move(label)),
      total_(std::max(total, 0)),
      lineEvery_(std::max(lineEvery, 1)),
      mode_(mode),
      out_(&out),
      start_(std::chrono::steady_clock::now()),
      lastLine_(start_) {}

ProgressBar::~ProgressBar() { finish(); }

std::string ProgressBar::formatDuration(double seconds) {
  if (!(seconds >= 0) || !std::isfinite(seconds)) return "--:--";
  const long s = std::lround(seconds);
  if (s >= 3600) return fmt::format("{}:{:02d}:{:02d}", s / 3600, (s / 60) % 60, s % 60);
  return fmt::format("{}:{:02d}", s / 60, s % 60);
}

std::string ProgressBar::render(const std::string& label, int done, int total,
                                double elapsedSeconds, double etaSeconds, const std::string& note,
                                int width) {
  const double frac = total > 0 ? std::clamp(static_cast<double>(done) / total, 0.0, 1.0) : 1.0;
  const int filled = static_cast<int>(std::floor(frac * width + 1e-9));
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.append(static_cast<std::size_t>(width - filled), '.');
  std::string line = fmt::format("{} [{}] {}/{}  elapsed {}  ETA {}", label, bar, done, total,
                                 formatDuration(elapsedSeconds), formatDuration(etaSeconds));
  if (!note.empty()) line += "  " + note;
  return line;
}

std::string ProgressBar::renderLine(const std::string& label, int done, int total, double elapsedSeconds,
                                    double etaSeconds, const std::string& note) {
  std::string line = fmt::format("{}: {}/{}  elapsed {}  ETA {}", label, done, total,
                                 formatDuration(elapsedSeconds), formatDuration(etaSeconds));
  if (!note.empty()) line += "  " + note;
  return line;
}

void ProgressBar::skip(int count) { skipped_ += std::max(count, 0); }

void ProgressBar::stage(const std::string& name) {
  if (finished_ || name == stage_) return;
  stage_ = name;
  if (mode_ == ProgressMode::Lines) {
    *out_ << label_ << ": " << name << "\n" << std::flush;
    lastLine_ = std::chrono::steady_clock::now();
  }
}

void ProgressBar::update(int done, const std::string& note) {
  if (mode_ == ProgressMode::Silent || finished_) return;
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const int timed = done - skipped_;
  const double eta = timed > 0 ? elapsed / timed * (total_ - done) : -1.0;
  const std::string shown = note.empty() ? stage_ : note;
  if (mode_ == ProgressMode::Bar) {
    *out_ << "\r" << render(label_, done, total_, elapsed, eta, shown) << "\033[K" << std::flush;
    drawn_ = true;
    return;
  }
  // Lines: a further multiple of lineEvery (or the end) reached; with -v also every new note;
  // and a new note once no line was written for the heartbeat (a long step shows it is alive).
  const bool step = done > lastLineDone_ && done > skipped_ &&
                    (done / lineEvery_ > std::max(lastLineDone_, 0) / lineEvery_ || done == total_);
  const bool newNote = !note.empty() && note != lastNote_;
  const bool verboseNote = newNote && verbosity() == Verbosity::Verbose;
  const bool heartbeat = newNote && std::chrono::duration<double>(now - lastLine_).count() >= heartbeatSeconds_;
  if (step || verboseNote || heartbeat) {
    *out_ << renderLine(label_, done, total_, elapsed, eta, note) << "\n" << std::flush;
    lastLine_ = now;
  }
  if (step) lastLineDone_ = done;
  lastNote_ = note;
}

void ProgressBar::finish() {
  if (finished_) return;
  finished_ = true;
  if (mode_ == ProgressMode::Bar && drawn_) *out_ << "\n" << std::flush;
}

}  // namespace mesochain
