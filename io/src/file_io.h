// Whole-file reads and all-or-nothing writes, shared by the volume-mesh and PLC-file code.
#pragma once
#include <charconv>
#include <cstdint>
#include <filesystem>
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
