// The sweepcdt command's exit codes: one per kind of outcome, so scripts can tell a bad input from a
// surface without a CDT from a full disk. Documented in `sweepcdt --help` (usage.cpp) and the README.
#pragma once

namespace sweepcdt::cli {

enum ExitCode : int {
  kOk = 0,
  kInternal = 1,      // a bug or resource exhaustion (out of memory): not the user's input
  kUsage = 2,         // bad command line (also: an option this version does not support yet)
  kBadInput = 3,      // unreadable or invalid input (io::InputError, io::SurfaceError, PlcError)
  kNoCdt = 4,         // the input has no CDT (NoCdtError), with the Steiner mode asked for
  kWriteFailed = 5,   // an output could not be written (nothing is left under its name)
  kNotValid = 6,      // `check`, or `--check`: the triangulation is not the CDT of the input
  kCancelled = 130,   // Ctrl-C (SIGINT), as shells report a process killed by it: 128 + 2
};

// Batch runs exit with the worst outcome; "worse" is this order, not the numeric value
// (a cancelled run outranks everything, an internal error everything else).
inline int severity(int code) {
  switch (code) {
    case kOk: return 0;
    case kNotValid: return 1;
    case kNoCdt: return 2;
    case kBadInput: return 4;
    case kWriteFailed: return 5;
    case kUsage: return 6;
    case kInternal: return 7;
    case kCancelled: return 8;
  }
  return 7;
}

inline int worst(int a, int b) { return severity(a) >= severity(b) ? a : b; }

}  // namespace sweepcdt::cli
