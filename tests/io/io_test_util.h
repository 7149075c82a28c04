// Helpers for the io tests: temporary files, and expecting an InputError of a kind at a place.
#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "sweepcdt/io/error.h"
#include "sweepcdt/io/read.h"

namespace sweepcdt::io::testing {

// A fresh directory under the system's temporary directory, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    // The process id keeps concurrent runs of the same test (ctest -j runs the whole binary too) apart.
    path_ = std::filesystem::temp_directory_path() /
            ("sweepcdt_io_" + std::to_string(::getpid()) + "_" + info->test_suite_name() + "_" + info->name());
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  std::filesystem::path write(const std::string& name, const std::string& bytes) const {
    const auto file = path_ / name;
    std::ofstream(file, std::ios::binary) << bytes;
    return file;
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// Reads `bytes` as file `name`; expects an InputError of `kind` whose message names the file and
// contains `where` (e.g. ":4:" for line 4, "byte 80", "face 2").
inline void expect_input_error(const std::string& name, const std::string& bytes, InputErrorKind kind, const std::string& where) {
  try {
    read_soup_from_memory(bytes, name, std::filesystem::path(name).extension().string());
    ADD_FAILURE() << name << " was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(name, 0), 0u) << "message does not start with the file name: " << what;
    EXPECT_NE(what.find(where), std::string::npos) << "message does not say '" << where << "': " << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << "one line: " << what;
  }
}

// Writes `text` as file `name` in `dir` and reads it with `read(path)`; expects an InputError of
// `kind` whose message names the file and contains `where`.
template <class Read>
void expect_file_error(const TempDir& dir, const std::string& name, const std::string& text, InputErrorKind kind,
                       const std::string& where, Read read) {
  const auto file = dir.write(name, text);
  try {
    read(file);
    ADD_FAILURE() << name << " was accepted:\n" << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
    EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << "expected '" << where << "' in: " << e.what();
  }
}

}  // namespace sweepcdt::io::testing
