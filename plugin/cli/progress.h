// Progress and Ctrl-C for long conversions.
//
// Ctrl-C: the SIGINT handler only sets a flag (all a handler may safely do); the progress callback
// passed to cdt() (Options::progress) returns false once it is set, so cdt() throws CancelledError
// and the command exits cleanly with kCancelled, writing nothing for the file in progress. The
// handler then restores the default action: a second Ctrl-C kills at once.
//
// Display: a one-line bar, redrawn in place, when stderr is a terminal and the work has lasted over a
// second (short runs stay silent until their summary line); plain log lines otherwise, one per phase
// that starts after the first second, prefixed with the file (several files may run at once).
#pragma once
#include <chrono>
#include <functional>
#include <iosfwd>
#include <mutex>
#include <string>

#include "sweepcdt/cdt.h"

namespace sweepcdt::cli {

void install_interrupt_handler();
bool interrupted();
// Throws CancelledError if Ctrl-C was pressed (between phases that have no callback of their own).
void throw_if_interrupted();

// Serialises whole lines on stderr between threads.
class Console {
 public:
  Console(std::ostream& err, bool quiet);
  bool quiet() const { return quiet_; }
  bool terminal() const { return terminal_; }
  void line(const std::string& text);  // one line, even when quiet (errors)
  void info(const std::string& text);  // one line unless quiet
  void bar(const std::string& text);   // redraw the bar (terminal only)

 private:
  void clear_bar_locked();
  std::ostream& err_;
  bool quiet_;
  bool terminal_;
  bool bar_shown_ = false;
  std::mutex mutex_;
};

// Progress of one file's conversion.
class FileProgress {
 public:
  // `bar`: draw a bar (only one file runs at a time); else log lines.
  // The bar stays until the next Console::line() (the file's summary or error) replaces it.
  FileProgress(Console& console, std::string label, bool bar);
  // Phases without a callback of their own ("reading", "writing").
  void phase(const std::string& name);
  // For Options::progress.
  std::function<bool(const Progress&)> callback();

 private:
  void report(const std::string& phase, uint64_t done, uint64_t total);
  double elapsed() const;

  Console& console_;
  std::string label_;
  bool bar_;
  std::string phase_;         // the phase last reported
  std::string logged_phase_;  // the phase of the last log line: a phase that began in the quiet
                              // first second is logged once the second has passed
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  double last_draw_ = -1;
};

}  // namespace sweepcdt::cli
