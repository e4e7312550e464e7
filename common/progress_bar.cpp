#include "common/progress_bar.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>

#include <fmt/format.h>
#include <unistd.h>

namespace mesochain {

bool progressOutputEnabled() {
  const char* ci = std::getenv("CI");
  if (ci && std::strcmp(ci, "true") == 0) return false;
  return isatty(STDERR_FILENO) != 0;
}

ProgressBar::ProgressBar(std::string label, int total)
    : label_(std::move(label)),
      total_(std::max(total, 0)),
      enabled_(progressOutputEnabled()),
      start_(std::chrono::steady_clock::now()) {}

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

void ProgressBar::skip(int count) { skipped_ += std::max(count, 0); }

void ProgressBar::update(int done, const std::string& note) {
  if (!enabled_ || finished_) return;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const int timed = done - skipped_;
  const double eta = timed > 0 ? elapsed / timed * (total_ - done) : -1.0;
  std::cerr << "\r" << render(label_, done, total_, elapsed, eta, note) << "\033[K" << std::flush;
  drawn_ = true;
}

void ProgressBar::finish() {
  if (finished_) return;
  finished_ = true;
  if (enabled_ && drawn_) std::cerr << "\n" << std::flush;
}

}  // namespace mesochain
