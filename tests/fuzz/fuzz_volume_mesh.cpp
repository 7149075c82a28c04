// libFuzzer target for one volume-mesh reader (SWEEPCDT_FUZZ_MESH_READER: read_medit, read_vtu,
// read_gmsh, read_abaqus) or the .plc text reader, followed, when the input reads, by writing it back
// in every format to memory (the writers' consistency checks run first, as in write_volume_mesh()).
// Any exception other than sweepcdt::Error escapes, so libFuzzer reports it; so do crashes and
// sanitizer findings.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "poly_files.h"
#include "volume_mesh_formats.h"

namespace {

void run(const std::string& bytes) {
  using namespace sweepcdt::io::detail;
  const std::string name = "fuzz-input";
#ifdef SWEEPCDT_FUZZ_PLC_TEXT
  read_plc_text(bytes, name);
#else
  const sweepcdt::io::VolumeMesh mesh = SWEEPCDT_FUZZ_MESH_READER(bytes, name);
  check_read(mesh, name);
  check_writable(mesh, name);
  medit_text(mesh);
  vtu_text(mesh);
  gmsh_text(mesh, false);
  gmsh_text(mesh, true);
  abaqus_text(mesh);
  tetgen_texts(mesh);
#endif
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  try {
    run(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const sweepcdt::Error&) {
    // Rejected with a typed error: the expected outcome for malformed input.
  }
  return 0;
}
