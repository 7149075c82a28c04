// Progress and Ctrl-C, as a user sees them: a bar on a terminal, log lines in a file, and SIGINT
// ending a run (single or batch) with exit 130 and nothing written.
#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <functional>
#include <mutex>
#include <thread>

#include <fcntl.h>
#include <pty.h>
#include <spawn.h>
#include <unistd.h>

#include "cli_run.h"

extern char** environ;

namespace sweepcdt::cli::testing {
namespace {

// Gift-wrapping these takes far longer than the tests wait: they are always interrupted.
const fs::path kLongInput = shared_data() / "stl_binary/thingi_1706459.stl";

// Hang guard only: the runs below reach the awaited output within a few seconds of work; this bounds
// a broken run, it is not a timing the tests rely on.
constexpr auto kHangGuard = std::chrono::minutes(5);

// Runs sweepcdt with `words`, stderr to `log` (or to `stderr_fd`), and sends SIGINT once `reached()`
// says the output shows the point under test — an event of the run itself, never a fixed delay, so
// the tests do not depend on how fast the machine is. The exit status, and how long the process took
// to end after the signal.
std::pair<int, double> run_and_interrupt(std::vector<std::string> words, const std::string& log, const std::function<bool()>& reached,
                                         int stderr_fd = -1) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (stderr_fd >= 0) posix_spawn_file_actions_adddup2(&actions, stderr_fd, 2);
  else posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  words.insert(words.begin(), SWEEPCDT_CLI);
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  // On the pseudo-terminal, a terminal that can redraw (CI may run with TERM=dumb or none).
  std::vector<std::string> env_words{"TERM=xterm"};
  for (char** e = environ; *e; ++e)
    if (std::string(*e).rfind("TERM=", 0) != 0) env_words.push_back(*e);
  std::vector<char*> env;
  for (auto& w : env_words) env.push_back(w.data());
  env.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, SWEEPCDT_CLI, &actions, nullptr, argv.data(), stderr_fd >= 0 ? env.data() : environ) != 0) return {-1, 0};
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  const auto give_up = std::chrono::steady_clock::now() + kHangGuard;
  while (!reached()) {
    if (::waitpid(pid, &status, WNOHANG) == pid) {  // ended before the awaited output: the caller's checks say why
      ADD_FAILURE() << "sweepcdt ended before the awaited output";
      return {status, 0};
    }
    if (std::chrono::steady_clock::now() > give_up) {
      ADD_FAILURE() << "the awaited output did not come (hang guard)";
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ::kill(pid, SIGINT);
  const auto sent = std::chrono::steady_clock::now();
  ::waitpid(pid, &status, 0);
  return {status, std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count()};
}

// `reached` for run_and_interrupt: the log file holds `text`.
std::function<bool()> log_says(const std::string& log, const std::string& text) {
  return [=] { return bytes_of(log).find(text) != std::string::npos; };
}

// Ctrl-C during a long run (gift-wrapping the refined thingi surface takes minutes; the knot, which
// these tests used, now takes 2 s): exit 130, a message, no output.
TEST(CliProgress, CtrlCCancelsCleanly) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  const std::string input = kLongInput.string();
  const std::string log = (dir.path() / ".log").string();
  const auto [status, seconds] =
      run_and_interrupt({input, "-o", (dir.path() / "thingi.mesh").string(), "--algorithm", "giftwrap"}, log,
                        log_says(log, input + ": gift-wrapping ("));
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  EXPECT_EQ(WEXITSTATUS(status), 130) << bytes_of(log);
  EXPECT_LT(seconds, 10.0) << "cancellation took too long";
  EXPECT_NE(bytes_of(log).find(input + ": cancelled (Ctrl-C): nothing written"), std::string::npos) << bytes_of(log);
  EXPECT_TRUE(files_in(dir.path()).empty());
}

// In a batch: the files in progress stop, the rest never start, nothing is written, and --stats
// still records what happened.
TEST(CliProgress, CtrlCCancelsABatch) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  const auto out = dir.path() / "out";
  const std::string log = (dir.path() / ".log").string();
  // Two long runs (copies of one surface under two names), then a short one.
  const auto first = dir.path() / "first.stl", second = dir.path() / "second.stl";
  fs::copy_file(kLongInput, first);
  fs::copy_file(kLongInput, second);
  const auto [status, seconds] = run_and_interrupt(
      {"mesh", first.string(), second.string(), (shared_data() / "off/icosahedron.off").string(), "--out-dir", out.string(),
       "--threads", "2", "--algorithm", "giftwrap", "--stats", (dir.path() / "stats.json").string()},
      log, [&] {  // both threads busy gift-wrapping, so the third file cannot have started
        return log_says(log, first.string() + ": gift-wrapping (")() && log_says(log, second.string() + ": gift-wrapping (")();
      });
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  EXPECT_EQ(WEXITSTATUS(status), 130) << bytes_of(log);
  EXPECT_LT(seconds, 10.0) << "cancellation took too long";
  EXPECT_NE(bytes_of(log).find("1 files not started"), std::string::npos) << bytes_of(log);
  EXPECT_TRUE(files_in(out).empty());
  const auto stats = nlohmann::json::parse(bytes_of(dir.path() / "stats.json"));
  EXPECT_EQ(stats["exit_code"], 130);
  ASSERT_EQ(stats["files"].size(), 3u);
  for (const auto& f : stats["files"]) EXPECT_EQ(f["status"], "cancelled") << f;
}

// On a terminal (a pseudo-terminal here), a bar redrawn in place once the work passes a second; in a
// file, plain log lines without escape sequences.
TEST(CliProgress, BarOnATerminalLogLinesOtherwise) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  int master = -1, slave = -1;
  ASSERT_EQ(::openpty(&master, &slave, nullptr, nullptr, nullptr), 0);
  std::string screen;
  std::mutex screen_mutex;
  std::thread reader([&] {
    char buf[4096];
    for (ssize_t n; (n = ::read(master, buf, sizeof buf)) > 0;) {
      std::lock_guard lock(screen_mutex);
      screen.append(buf, static_cast<std::size_t>(n));
    }
  });
  // The bar is drawn once the work passes a second; interrupt when it has shown a percentage.
  const std::string bar = "\r\033[K" + kLongInput.string() + ": gift-wrapping [";
  const auto [status, seconds] = run_and_interrupt(
      {kLongInput.string(), "-o", (dir.path() / "k.mesh").string(), "--algorithm", "giftwrap"}, "",
      [&] {
        std::lock_guard lock(screen_mutex);
        const auto at = screen.find(bar);
        return at != std::string::npos && screen.find('%', at) != std::string::npos;
      },
      slave);
  ::close(slave);  // the reader sees EOF (EIO) once the child's copy is gone too
  reader.join();
  ::close(master);
  EXPECT_EQ(WEXITSTATUS(status), 130) << screen;
  EXPECT_NE(screen.find(bar), std::string::npos) << screen;
  EXPECT_NE(screen.find("%"), std::string::npos) << screen;

  const std::string log = (dir.path() / ".log").string();
  const auto [log_status, log_seconds] =
      run_and_interrupt({kLongInput.string(), "-o", (dir.path() / "k.mesh").string(), "--algorithm", "giftwrap"}, log,
                        log_says(log, kLongInput.string() + ": gift-wrapping ("));
  EXPECT_EQ(WEXITSTATUS(log_status), 130);
  const std::string text = bytes_of(log);
  EXPECT_NE(text.find(kLongInput.string() + ": gift-wrapping ("), std::string::npos) << text;
  EXPECT_EQ(text.find('\033'), std::string::npos) << text;
  EXPECT_EQ(text.find('\r'), std::string::npos) << text;
  EXPECT_TRUE(files_in(dir.path()).empty());
}

}  // namespace
}  // namespace sweepcdt::cli::testing
