// Uses an installed sweepcdt through find_package(sweepcdt): reads a surface with sweepcdt::io,
// builds its CDT and validates it.
#include <cstdio>

#include "sweepcdt/cdt.h"
#include "sweepcdt/io/read.h"
#include "sweepcdt/validate.h"

int main() {
  // A tetrahedron's surface, counterclockwise seen from outside.
  const char* off = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const sweepcdt::io::Soup soup = sweepcdt::io::read_soup_from_memory(off, "tetrahedron.off", ".off");
  sweepcdt::Plc<3> plc;
  plc.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1, 0.5, 0.25, 0.125};
  const auto tri = sweepcdt::cdt(plc);
  const bool ok = sweepcdt::validate(tri, plc).ok() && soup.points.size() == 12;
  std::printf("%s\n", ok ? "valid" : "INVALID");
}
