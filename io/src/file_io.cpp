// read_file_bytes() and write_files_atomically(): temporary files beside the target, then rename.
#include "file_io.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "reader_util.h"
#include "sweepcdt/io/read.h"

namespace sweepcdt::io::detail {
namespace {

std::atomic<uint64_t> temporary_counter{0};

// Creates a new, empty temporary file in `target`'s folder; its descriptor, or -1 with errno set.
// Mode 0666 through the umask, like the file the user asked for.
int create_temporary(const std::filesystem::path& target, std::filesystem::path& temporary) {
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  for (int attempt = 0; attempt < 100; ++attempt) {
    temporary = folder / ("." + target.filename().string() + "." + std::to_string(::getpid()) + "." +
                          std::to_string(temporary_counter++) + ".part");
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  return -1;
}

bool write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

std::string read_file_bytes(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    fail(InputErrorKind::Unreadable, name, Location::none(), ec ? ec.message() : "not a regular file");
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) fail(InputErrorKind::Unreadable, name, Location::none(), ec.message());
  if (size > kMaxFileBytes)
    fail(InputErrorKind::Unsupported, name, Location::none(), "files larger than " + std::to_string(kMaxFileBytes) + " bytes");
  std::ifstream in(file, std::ios::binary);
  std::string bytes(size, '\0');
  if (!in || !in.read(bytes.data(), static_cast<std::streamsize>(size)))
    fail(InputErrorKind::Unreadable, name, Location::none(), "cannot read the file");
  return bytes;
}

void write_files_atomically(const std::vector<std::pair<std::filesystem::path, std::string>>& files, const std::string& name) {
  std::vector<std::pair<std::filesystem::path, TextMaker>> makers;
  for (const auto& [target, bytes] : files) makers.emplace_back(target, [&bytes = bytes](TextOut& out) { out.flush(bytes); });
  write_files_atomically(makers, name);
}

void write_files_atomically(const std::vector<std::pair<std::filesystem::path, TextMaker>>& files, const std::string& name) {
  std::vector<std::filesystem::path> temporaries;
  auto remove_temporaries = [&] {
    std::error_code ignored;
    for (const auto& t : temporaries) std::filesystem::remove(t, ignored);
  };
  auto give_up = [&](const std::filesystem::path& which, const std::string& why) {
    remove_temporaries();
    fail(InputErrorKind::Unreadable, name, Location::none(), "cannot write " + which.string() + ": " + why);
  };
  for (const auto& [target, make] : files) {
    std::filesystem::path temporary;
    const int fd = create_temporary(target, temporary);
    if (fd < 0) give_up(target, std::strerror(errno));
    temporaries.push_back(temporary);
    TextOut out;
    out.flush = [&](const std::string& bytes) {
      if (!write_all(fd, bytes)) give_up(target, std::strerror(errno));  // a full disk: stop at once
    };
    try {
      make(out);
      out.flush(out.text);
    } catch (...) {  // that, or the writer's own error (memory): nothing left behind
      ::close(fd);
      remove_temporaries();
      throw;
    }
    // close() reports delayed write errors (NFS, full disks), so it decides too.
    if (::close(fd) != 0) give_up(target, std::strerror(errno));
  }
  // A folder under a target name would make its rename fail; find out before renaming any, so a set
  // of files is not left half replaced for that (the common) reason.
  for (const auto& [target, make] : files) {
    std::error_code ec;
    if (std::filesystem::is_directory(target, ec)) give_up(target, "a folder of that name exists");
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::error_code ec;
    std::filesystem::rename(temporaries[i], files[i].first, ec);
    if (ec) {
      temporaries.erase(temporaries.begin(), temporaries.begin() + static_cast<std::ptrdiff_t>(i));
      give_up(files[i].first, ec.message());
    }
  }
}

}  // namespace sweepcdt::io::detail
