// sweepcdt's .plc text (any D = 2..5; grammar in io/README.md):
//   plc D
//   points N            then N lines of D coordinates
//   simplices M         then M lines: D point ids (0-based) [exterior side: + | - | 0 [tag]]
//   seeds K             (optional) then K lines: D coordinates and a region id
// '#' starts a comment. Sides: '+' = the positive side is exterior, '-' = the negative side, '0' =
// neither. No side on any line: the domain is the convex hull. Tags: on every line or on none.
#include "poly_files.h"

namespace sweepcdt::io::detail {
namespace {

template <int D>
Plc<D> read_body(TextScanner& in) {
  Plc<D> plc;
  std::vector<std::string_view> line;
  auto header = [&](const char* word, uint64_t min_bytes_each) {
    if (!in.next_line(line)) in.fail(InputErrorKind::Truncated, std::string("the file ends before '") + word + "'");
    if (line.size() != 2 || line[0] != word) in.fail(InputErrorKind::Syntax, std::string("expected '") + word + " <count>'");
    const auto count = static_cast<uint64_t>(in.to_integer(line[1], "a count", 0, INT64_MAX));
    if (count > in.bytes_left() / min_bytes_each)
      in.fail(InputErrorKind::AbsurdCount, std::to_string(count) + " " + word + " announced, but only " + std::to_string(in.bytes_left()) + " bytes follow");
    return count;
  };
  const uint64_t n = header("points", 2 * D);
  if (n >= kNone) in.fail(InputErrorKind::AbsurdCount, "more than 2^32 - 2 points");
  plc.points.reserve(n * D);
  for (uint64_t i = 0; i < n; ++i) {
    if (!in.next_line(line)) in.fail(InputErrorKind::Truncated, "the file ends inside the points");
    if (line.size() != D) in.fail(InputErrorKind::Syntax, "a point has " + std::to_string(D) + " coordinates, this line has " + std::to_string(line.size()) + " numbers");
    for (const auto& t : line) plc.points.push_back(in.to_double(t, "a coordinate"));
  }
  const uint64_t m = header("simplices", 2 * D);
  bool any_side = false, any_tag = false;
  for (uint64_t j = 0; j < m; ++j) {
    if (!in.next_line(line)) in.fail(InputErrorKind::Truncated, "the file ends inside the simplices");
    if (line.size() < D || line.size() > D + 2) in.fail(InputErrorKind::Syntax, "a simplex line is " + std::to_string(D) + " point ids, an optional side (+, -, 0) and an optional tag");
    for (int k = 0; k < D; ++k) {
      const int64_t v = in.to_integer(line[k], "a point id");
      if (v < 0 || static_cast<uint64_t>(v) >= n) in.fail(InputErrorKind::IndexOutOfRange, "point " + std::to_string(v) + " does not exist (" + std::to_string(n) + " points, from 0)");
      plc.simplices.push_back(static_cast<uint32_t>(v));
    }
    ExteriorSide side = ExteriorSide::None;
    if (line.size() > D) {
      if (line[D] == "+") side = ExteriorSide::Positive;
      else if (line[D] == "-") side = ExteriorSide::Negative;
      else if (line[D] != "0") in.fail(InputErrorKind::Syntax, "the exterior side is '+', '-' or '0'");
      any_side = true;
    }
    plc.exterior.push_back(side);
    const bool tagged = line.size() == D + 2;
    if (j > 0 && tagged != any_tag) in.fail(InputErrorKind::Syntax, "tags must be on every simplex line or on none");
    any_tag = tagged;
    if (tagged) plc.tags.push_back(static_cast<uint32_t>(in.to_integer(line[D + 1], "a tag", 0, UINT32_MAX - 1)));
  }
  if (!any_side) plc.exterior.clear();
  if (in.next_line(line)) {
    if (line.size() != 2 || line[0] != "seeds") in.fail(InputErrorKind::Syntax, "expected 'seeds <count>' or the end of the file");
    const auto k = static_cast<uint64_t>(in.to_integer(line[1], "a count", 0, INT64_MAX));
    if (k > in.bytes_left() / (2 * (D + 1))) in.fail(InputErrorKind::AbsurdCount, std::to_string(k) + " seeds announced, but only " + std::to_string(in.bytes_left()) + " bytes follow");
    for (uint64_t i = 0; i < k; ++i) {
      if (!in.next_line(line)) in.fail(InputErrorKind::Truncated, "the file ends inside the seeds");
      if (line.size() != D + 1) in.fail(InputErrorKind::Syntax, "a seed line is " + std::to_string(D) + " coordinates and a region id");
      RegionSeed<D> seed{};
      for (int c = 0; c < D; ++c) seed.point[c] = in.to_double(line[c], "a coordinate");
      seed.region = static_cast<int32_t>(in.to_integer(line[D], "a region id", 0, INT32_MAX - 1));
      plc.region_seeds.push_back(seed);
    }
    if (in.next_line(line)) in.fail(InputErrorKind::Syntax, "unexpected text after the seeds");
  }
  return plc;
}

}  // namespace

AnyPlc read_plc_text(const std::string& bytes, const std::string& file) {
  TextScanner in(bytes, file, '#');
  std::vector<std::string_view> line;
  if (!in.next_line(line)) fail(InputErrorKind::Truncated, file, Location::none(), "the file is empty");
  if (line.size() != 2 || line[0] != "plc") in.fail(InputErrorKind::Syntax, "a .plc file starts with 'plc <dimension>'");
  switch (in.to_integer(line[1], "the dimension")) {
    case 2: return read_body<2>(in);
    case 3: return read_body<3>(in);
    case 4: return read_body<4>(in);
    case 5: return read_body<5>(in);
    default: in.fail(InputErrorKind::Unsupported, "dimension " + std::string(line[1]) + " (2 to 5)");
  }
}

}  // namespace sweepcdt::io::detail
