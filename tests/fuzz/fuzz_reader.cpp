// libFuzzer target for one reader (chosen at compile time by SWEEPCDT_FUZZ_READER), followed by
// welding, inspection and conversion to a PLC when the input reads. Any exception other than
// sweepcdt::Error is a bug and escapes, so libFuzzer reports it; so do crashes and sanitizer findings.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "reader_util.h"
#include "sweepcdt/io/surface.h"
#include "sweepcdt/io/to_plc.h"

namespace sweepcdt::io::detail {
// The glTF reader's two flavours as one-argument-pair readers, like the others.
inline void read_gltf_text(std::string_view bytes, Soup& soup) { read_gltf(bytes, soup, false); }
inline void read_glb(std::string_view bytes, Soup& soup) { read_gltf(bytes, soup, true); }
}  // namespace sweepcdt::io::detail

namespace {

// inspect() is O(m log m) but its exact tests are slow for pathological inputs; keep runs fast.
constexpr std::size_t kMaxInspectedTriangles = 2000;

void read(std::string_view bytes, sweepcdt::io::Soup& soup) {
  using namespace sweepcdt::io::detail;
  // A name in a directory that does not exist: glTF's external buffers resolve to nothing.
  soup.file = "/nonexistent-fuzz-dir/input";
  SWEEPCDT_FUZZ_READER(bytes, soup);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  sweepcdt::io::Soup soup;
  try {
    read(bytes, soup);
    if (soup.num_triangles() > kMaxInspectedTriangles) return 0;
    const sweepcdt::io::Surface surface = sweepcdt::io::weld(soup);
    const sweepcdt::io::SurfaceReport report = sweepcdt::io::inspect(surface);
    if (report.valid()) sweepcdt::io::to_plc(surface, report);
  } catch (const sweepcdt::Error&) {
    // Rejected with a typed error: the expected outcome for malformed input.
  }
  return 0;
}
