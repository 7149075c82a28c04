#include "errors.h"

#include <algorithm>
#include <filesystem>
#include <new>
#include <sstream>

#include "exit_codes.h"
#include "sweepcdt/cdt.h"
#include "sweepcdt/io/error.h"

namespace sweepcdt::cli {
namespace {

constexpr std::size_t kDetailsShown = 5;

// The library's multi-line messages: the first line is the summary, the rest are problems.
Failure split_lines(int code, const std::string& text, const std::string& prefix) {
  Failure f{code, {}, {}};
  std::istringstream in(text);
  std::string line;
  std::size_t more = 0;
  while (std::getline(in, line)) {
    if (f.message.empty()) f.message = prefix + line;
    else if (f.details.size() < kDetailsShown) {
      const std::size_t indent = std::min(line.find_first_not_of(' '), line.size());
      f.details.push_back(prefix);
      f.details.back().append(line, indent);
    }
    else ++more;
  }
  if (more) f.details.push_back(prefix + "... " + std::to_string(more) + " more lines");
  return f;
}

std::string ids_text(const std::vector<uint32_t>& ids) {
  std::string s;
  for (uint32_t id : ids) s += (s.empty() ? "" : " ") + std::to_string(id);
  return s;
}

}  // namespace

Failure describe_current_exception(const std::string& file, bool writing) {
  const std::string prefix = file.empty() ? "" : file + ": ";
  try {
    throw;
  } catch (const io::InputError& e) {
    return {writing ? kWriteFailed : kBadInput, e.what(), {}};  // writers throw InputError(Unreadable)
  } catch (const io::SurfaceError& e) {
    return split_lines(kBadInput, e.what(), "");  // names its file on every line already
  } catch (const PlcError& e) {
    return split_lines(kBadInput, e.what(), prefix);
  } catch (const NoCdtError& e) {
    Failure f{kNoCdt, prefix + e.what(), {}};
    if (!e.witness().empty()) f.message += " (witness vertices " + ids_text(e.witness()) + ", 0-based input ids)";
    return f;
  } catch (const CancelledError&) {
    return {kCancelled, prefix + "cancelled (Ctrl-C): nothing written", {}};
  } catch (const std::filesystem::filesystem_error& e) {
    if (writing) return {kWriteFailed, e.path1().string() + ": cannot write: " + e.code().message(), {}};
    return {kBadInput, e.path1().string() + ": " + e.code().message(), {}};
  } catch (const std::bad_alloc&) {
    return {kInternal, prefix + "out of memory", {}};
  } catch (const std::exception& e) {
    return {kInternal, prefix + "internal error: " + e.what(), {}};
  } catch (...) {
    return {kInternal, prefix + "internal error: unknown exception", {}};
  }
}

}  // namespace sweepcdt::cli
