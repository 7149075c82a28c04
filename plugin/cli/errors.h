// Maps the library's typed errors to what the user reads and to the exit code (exit_codes.h).
#pragma once
#include <exception>
#include <string>
#include <vector>

namespace sweepcdt::cli {

struct Failure {
  int code;                          // exit code
  std::string message;               // one line: "FILE: what is wrong"
  std::vector<std::string> details;  // the first problems, one line each (printed unless --quiet)
};

// What the exception in flight means for `file` (the input; the library's messages already name the
// file they are about). `writing`: it was thrown while writing an output, so io::InputError and
// filesystem errors mean the output could not be written. Call from a catch block.
Failure describe_current_exception(const std::string& file, bool writing = false);

}  // namespace sweepcdt::cli
