// A small command-line reader shared by the subcommands: `--name value` and `--name=value`, flags,
// positionals; anything it does not recognise is a UsageError (exit 2 with the usage text).
#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace sweepcdt::cli {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ArgReader {
 public:
  explicit ArgReader(std::vector<std::string> args) : args_(std::move(args)) {}

  bool done() const { return next_ >= args_.size(); }
  const std::string& peek() const { return args_[next_]; }
  // The current argument is an option (starts with '-' and is not "-" alone).
  bool at_option() const { return !done() && peek().size() > 1 && peek()[0] == '-'; }

  // Consumes `name` (a flag); "--name=x" is a usage error.
  bool flag(const char* name);
  // Consumes `name VALUE` or `name=VALUE`; a missing value is a usage error.
  bool value(const char* name, std::string& out);
  std::string take() { return args_[next_++]; }

 private:
  std::vector<std::string> args_;
  std::size_t next_ = 0;
};

// "--threads 4" -> 4; anything but a positive integer up to `max` is a usage error naming `option`.
unsigned parse_count(const std::string& option, const std::string& text, unsigned max);

}  // namespace sweepcdt::cli
