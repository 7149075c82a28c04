#include "progress.h"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <ostream>

#include <unistd.h>

namespace sweepcdt::cli {
namespace {

// Read by every worker thread, written by the handler: a lock-free atomic is safe in both roles
// (a volatile sig_atomic_t would be a data race between threads).
std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void on_sigint(int) {
  g_interrupted.store(true);
  std::signal(SIGINT, SIG_DFL);  // a second Ctrl-C ends the process at once
}

constexpr double kQuietSeconds = 1.0;    // work shorter than this shows no progress at all
constexpr double kRedrawSeconds = 0.1;   // bar refresh
constexpr int kBarWidth = 30;

}  // namespace

void install_interrupt_handler() { std::signal(SIGINT, on_sigint); }
bool interrupted() { return g_interrupted.load(std::memory_order_relaxed); }
void throw_if_interrupted() {
  if (interrupted()) throw CancelledError();
}

// A terminal that cannot move the cursor (TERM=dumb, e.g. an editor's shell buffer) gets log lines.
Console::Console(std::ostream& err, bool quiet) : err_(err), quiet_(quiet) {
  const char* term = std::getenv("TERM");
  terminal_ = ::isatty(STDERR_FILENO) != 0 && !(term && std::string(term) == "dumb");
}

void Console::clear_bar_locked() {
  if (bar_shown_) err_ << "\r\033[K";
  bar_shown_ = false;
}

void Console::line(const std::string& text) {
  std::lock_guard lock(mutex_);
  clear_bar_locked();
  err_ << text << "\n" << std::flush;
}

void Console::info(const std::string& text) {
  if (!quiet_) line(text);
}

void Console::bar(const std::string& text) {
  if (quiet_ || !terminal_) return;
  std::lock_guard lock(mutex_);
  err_ << "\r\033[K" << text << std::flush;
  bar_shown_ = true;
}

FileProgress::FileProgress(Console& console, std::string label, bool bar)
    : console_(console), label_(std::move(label)), bar_(bar && console.terminal()) {}

double FileProgress::elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

void FileProgress::phase(const std::string& name) { report(name, 0, 0); }

std::function<bool(const Progress&)> FileProgress::callback() {
  return [this](const Progress& p) {
    report(p.phase, p.done, p.total);
    return !interrupted();
  };
}

void FileProgress::report(const std::string& phase, uint64_t done, uint64_t total) {
  const double t = elapsed();
  if (console_.quiet() || t < kQuietSeconds) {
    phase_ = phase;
    return;
  }
  if (bar_) {
    if (t - last_draw_ < kRedrawSeconds && phase == phase_) return;
    last_draw_ = t;
    phase_ = phase;
    char buf[64];
    std::string text = label_ + ": " + phase + " ";
    if (phase == "steiner points") {
      // During Steiner refinement core reports the points added so far — a count, not a fraction
      // (how many more a surface needs is not known in advance).
      text += std::to_string(done) + " points added";
    } else if (total > 0) {
      const double f = std::min(1.0, static_cast<double>(done) / static_cast<double>(total));
      const int filled = static_cast<int>(f * kBarWidth);
      text += '[';
      text.append(filled, '#').append(kBarWidth - filled, '.') += ']';
      std::snprintf(buf, sizeof buf, " %3.0f%%", 100 * f);
      text += buf;
    }
    std::snprintf(buf, sizeof buf, "  %.1f s", t);
    console_.bar(text + buf);
  } else if (phase != logged_phase_) {
    // Log lines: one per phase change, so a log of a long batch shows where each file is.
    phase_ = logged_phase_ = phase;
    char buf[32];
    std::snprintf(buf, sizeof buf, " (%.1f s)", t);
    console_.info(label_ + ": " + phase + buf);
  }
}

}  // namespace sweepcdt::cli
