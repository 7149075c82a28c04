#include "info.h"

#include <cstdio>
#include <ostream>

#include "sweepcdt/io/read.h"
#include "sweepcdt/io/surface.h"

namespace sweepcdt::cli {
namespace {

using io::SurfaceReport;

std::string yes_no(bool b) { return b ? "yes" : "no"; }

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') out += '\\', out += static_cast<char>(c);
    else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else out += static_cast<char>(c);
  }
  return out + "\"";
}

std::string box_text(const std::array<double, 3>& p) { return "[" + number(p[0]) + ", " + number(p[1]) + ", " + number(p[2]) + "]"; }

std::string shell_role(const io::Shell& s) {
  if (!s.closed) return "open";
  return s.depth % 2 == 0 ? "body" : "cavity";
}

void print_text(const SurfaceReport& r, std::ostream& out) {
  out << "file:            " << r.file << "\n"
      << "format:          " << io::to_string(r.format) << "\n"
      << "triangles:       " << r.triangles << "\n"
      << "vertices:        " << r.points << " after welding (" << r.points_in_file << " in the file)\n"
      << "closed:          " << yes_no(r.closed) << "\n"
      << "manifold:        " << yes_no(r.manifold) << "\n"
      << "oriented:        " << yes_no(r.oriented) << (r.valid() && r.reversed_triangles ? " (repaired: " + std::to_string(r.reversed_triangles) + " triangles reversed)" : "") << "\n"
      << "shells:          " << r.shells.size() << " (" << r.closed_shells() << " closed, " << r.nested_shells() << " nested)\n";
  constexpr std::size_t kShellsShown = 20;
  for (std::size_t i = 0; i < r.shells.size() && i < kShellsShown; ++i) {
    const io::Shell& s = r.shells[i];
    out << "  shell " << i << ": " << s.triangles << " triangles from triangle " << s.first_triangle << ", " << (s.closed ? "closed" : "open");
    if (r.valid()) out << ", " << shell_role(s) << ", depth " << s.depth << (s.parent >= 0 ? ", inside shell " + std::to_string(s.parent) : "") << (s.reversed ? ", reversed" : "");
    out << "\n";
  }
  if (r.shells.size() > kShellsShown) out << "  ... and " << r.shells.size() - kShellsShown << " more\n";
  out << "self-intersecting pairs: " << (r.self_intersections_checked ? std::to_string(r.count(io::SurfaceProblemKind::SelfIntersection)) : "not checked") << "\n"
      << "bounding box:    " << box_text(r.box_min) << " - " << box_text(r.box_max) << "\n"
      << "valid:           " << yes_no(r.valid()) << "\n";
  if (r.triangles == 0) out << "problems:        no triangles\n";
  for (int k = 0; k < io::kSurfaceProblemKinds; ++k)
    if (r.counts[k]) out << "problems:        " << r.counts[k] << " " << io::to_string(static_cast<io::SurfaceProblemKind>(k)) << "\n";
  for (const auto& p : r.problems) out << r.file << ": " << p.message << "\n";
}

void print_json(const SurfaceReport& r, std::ostream& out) {
  out << "{\n  \"file\": " << json_string(r.file) << ",\n  \"format\": " << json_string(io::to_string(r.format))
      << ",\n  \"triangles\": " << r.triangles << ",\n  \"vertices_in_file\": " << r.points_in_file << ",\n  \"vertices\": " << r.points
      << ",\n  \"closed\": " << (r.closed ? "true" : "false") << ",\n  \"manifold\": " << (r.manifold ? "true" : "false")
      << ",\n  \"oriented\": " << (r.oriented ? "true" : "false") << ",\n  \"reversed_triangles\": " << r.reversed_triangles
      << ",\n  \"self_intersections_checked\": " << (r.self_intersections_checked ? "true" : "false")
      << ",\n  \"valid\": " << (r.valid() ? "true" : "false") << ",\n  \"bounding_box\": [" << box_text(r.box_min) << ", " << box_text(r.box_max) << "]"
      << ",\n  \"counts\": {";
  for (int k = 0; k < io::kSurfaceProblemKinds; ++k)
    out << (k ? ", " : "") << json_string(io::to_string(static_cast<io::SurfaceProblemKind>(k))) << ": " << r.counts[k];
  out << "},\n  \"shells\": [";
  for (std::size_t i = 0; i < r.shells.size(); ++i) {
    const io::Shell& s = r.shells[i];
    out << (i ? ",\n    " : "\n    ") << "{\"first_triangle\": " << s.first_triangle << ", \"triangles\": " << s.triangles
        << ", \"closed\": " << (s.closed ? "true" : "false") << ", \"depth\": " << s.depth << ", \"parent\": " << s.parent
        << ", \"reversed\": " << (s.reversed ? "true" : "false") << "}";
  }
  out << "],\n  \"problems\": [";
  for (std::size_t i = 0; i < r.problems.size(); ++i) {
    const auto& p = r.problems[i];
    out << (i ? ",\n    " : "\n    ") << "{\"kind\": " << json_string(io::to_string(p.kind)) << ", \"elements\": [";
    for (std::size_t e = 0; e < p.elements.size(); ++e) out << (e ? ", " : "") << p.elements[e];
    out << "], \"message\": " << json_string(p.message) << "}";
  }
  out << "]\n}\n";
}

}  // namespace

int run_info(const std::string& input, bool json, std::ostream& out, std::ostream& err) {
  try {
    const io::Surface surface = io::weld(io::read_soup(input));
    const SurfaceReport report = io::inspect(surface);
    json ? print_json(report, out) : print_text(report, out);
    return report.valid() ? 0 : 3;
  } catch (const io::InputError& e) {
    if (json) out << "{\n  \"file\": " << json_string(input) << ",\n  \"error\": " << json_string(io::to_string(e.kind())) << ",\n  \"message\": " << json_string(e.what()) << "\n}\n";
    err << "sweepcdt: " << e.what() << "\n";
    return 3;
  } catch (const Error& e) {
    err << "sweepcdt: " << e.what() << "\n";
    return 3;
  }
}

}  // namespace sweepcdt::cli
