// progress_line.cpp: ProgressLine, drawn with a carriage return and "erase to the end of line".
#include "progress_line.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <utility>

namespace rodshape::cli {

namespace {

/// "12 s", "3 min 5 s", "2 h 4 min".
std::string duration(double seconds) {
  const long s = std::lround(seconds);
  if (s < 60) return std::to_string(s) + " s";
  if (s < 3600) return std::to_string(s / 60) + " min " + std::to_string(s % 60) + " s";
  return std::to_string(s / 3600) + " h " + std::to_string(s % 3600 / 60) + " min";
}

}  // namespace

ProgressLine::ProgressLine(std::string what, std::string unit, bool enabled)
    : what_(std::move(what)),
      unit_(std::move(unit)),
      active_(enabled && isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

ProgressLine::~ProgressLine() {
  if (drawn_) std::fputs("\r\x1b[K", stderr);
}

void ProgressLine::update(int done, int total) {
  if (!active_ || total <= 0) return;
  const auto now = std::chrono::steady_clock::now();
  if (done < total && drawn_ && now - last_draw_ < std::chrono::milliseconds(200)) return;
  last_draw_ = now;
  drawn_ = true;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  std::string line = what_ + ": " + std::to_string(done) + "/" + std::to_string(total) + " " +
                     unit_ + ", " + duration(elapsed);
  if (done > 0 && done < total)
    line += ", about " + duration(elapsed / done * (total - done)) + " left";
  std::fprintf(stderr, "\r%s\x1b[K", line.c_str());
  std::fflush(stderr);
}

}  // namespace rodshape::cli
