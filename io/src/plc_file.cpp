// read_plc_file(): the format from the extension (.poly: the dimension its first line announces),
// then the reader for it.
#include "sweepcdt/io/plc_file.h"

#include <algorithm>
#include <cctype>

#include "file_io.h"
#include "poly_files.h"

namespace sweepcdt::io {

AnyPlc read_plc_file(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const std::string bytes = detail::read_file_bytes(file);
  if (ext == ".smesh") return detail::read_tetgen_poly(bytes, file, true);
  if (ext == ".poly") {
    if (detail::poly_dimension(bytes, file) == 2) return detail::read_triangle_poly(bytes, file);
    return detail::read_tetgen_poly(bytes, file, false);
  }
  if (ext == ".plc" || bytes.compare(0, 3, "plc") == 0) return detail::read_plc_text(bytes, name);
  detail::fail(InputErrorKind::UnknownFormat, name, Location::none(), "not a PLC file: .poly (Triangle 2D, TetGen 3D), .smesh or .plc");
}

}  // namespace sweepcdt::io
