// Whole-file reads and all-or-nothing writes, shared by the volume-mesh and PLC-file code.
#pragma once
#include <charconv>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace sweepcdt::io::detail {

// The bytes of a regular file (Unreadable / Unsupported InputError otherwise; at most kMaxFileBytes).
std::string read_file_bytes(const std::filesystem::path& file);

// Writes every (path, bytes) pair: each goes to a fresh temporary file beside its target (created
// with O_EXCL, so nothing else is clobbered), and only when all temporaries are complete and closed
// are they renamed over the targets, in order. On any failure the temporaries are removed and an
// InputError (Unreadable) naming `name` is thrown; targets not yet renamed are untouched. A rename
// failing after an earlier one succeeded (another process removing the folder meanwhile) cannot be
// undone: only then can a set of files end up mixed.
void write_files_atomically(const std::vector<std::pair<std::filesystem::path, std::string>>& files, const std::string& name);

// A file's text as a writer makes it: appended to `text`, with spill() called between records. Past
// a megabyte a spill hands the text so far to `flush` (the file being written) and empties it, so a
// large mesh's file is never whole in memory (the fine perforated tube's 9M tetrahedra: 330 MB of
// text). Without `flush` the text is kept whole (a writer's bytes as one string).
struct TextOut {
  std::string text;
  std::function<void(const std::string&)> flush;
  void spill() {
    if (flush && text.size() >= (std::size_t{1} << 20)) flush(text), text.clear();
  }
};
// A writer of one file's text into a TextOut.
using TextMaker = std::function<void(TextOut&)>;

// The same as write_files_atomically(), each file's text made and written piece by piece.
void write_files_atomically(const std::vector<std::pair<std::filesystem::path, TextMaker>>& files, const std::string& name);

// Shortest text that reads back as the same double (std::to_chars), so text output is exact.
inline void append_double(std::string& out, double x) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, end);
}

inline void append_int(std::string& out, int64_t v) {
  char buf[24];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, end);
}

}  // namespace sweepcdt::io::detail
