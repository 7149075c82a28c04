// Internal: "(3 17 42)" — vertex ids for error messages and validation reports.
#pragma once
#include <cstdint>
#include <string>

namespace sweepcdt::detail {

inline std::string ids_text(const uint32_t* ids, int count) {
  std::string s = "(";  // appended, not " " + ...: GCC 12 warns falsely (-Wrestrict) on that
  for (int i = 0; i < count; ++i) {
    if (i) s += ' ';
    s += std::to_string(ids[i]);
  }
  return s += ')';
}

}  // namespace sweepcdt::detail
