// Internal: the problems verify_cdt() finds (sweepcdt/verify_cdt.h), collected by the steps of the
// verification in their own files, and how they name points.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "sweepcdt/verify_cdt.h"

namespace sweepcdt::detail {

class Problems {
 public:
  static constexpr std::size_t kShown = 10;
  explicit Problems(MeshVerification& v) : v_(v) {}
  void add(const std::string& text) {
    if (v_.problems.size() < kShown) v_.problems.push_back(text);
    ++v_.total_problems;
  }
  bool any() const { return v_.total_problems > 0; }

 private:
  MeshVerification& v_;
};

// %.17g: the point's exact coordinates, so that a message can be replayed.
inline std::string point_text(const double* p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g, %.17g)", p[0], p[1], p[2]);
  return buf;
}

}  // namespace sweepcdt::detail
