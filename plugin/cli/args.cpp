#include "args.h"

#include <charconv>

namespace sweepcdt::cli {

bool ArgReader::flag(const char* name) {
  if (done()) return false;
  const std::string& a = peek();
  if (a == name) {
    ++next_;
    return true;
  }
  if (a.rfind(std::string(name) + "=", 0) == 0) throw UsageError(std::string(name) + " takes no value");
  return false;
}

bool ArgReader::value(const char* name, std::string& out) {
  if (done()) return false;
  const std::string& a = peek();
  const std::string prefix = std::string(name) + "=";
  if (a.rfind(prefix, 0) == 0) {
    out = a.substr(prefix.size());
    ++next_;
  } else if (a == name) {
    // A following "-x" is taken as the value only if it cannot be an option, so that
    // "-o --quiet" is reported as a missing value rather than writing a file named "--quiet".
    if (next_ + 1 >= args_.size() || (args_[next_ + 1].size() > 1 && args_[next_ + 1][0] == '-'))
      throw UsageError(std::string(name) + " needs a value");
    out = args_[next_ + 1];
    next_ += 2;
  } else {
    return false;
  }
  if (out.empty()) throw UsageError(std::string(name) + " needs a value");
  return true;
}

unsigned parse_count(const std::string& option, const std::string& text, unsigned max) {
  unsigned n = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (ec != std::errc() || end != text.data() + text.size() || n == 0 || n > max)
    throw UsageError(option + " needs a whole number from 1 to " + std::to_string(max) + ", not '" + text + "'");
  return n;
}

}  // namespace sweepcdt::cli
