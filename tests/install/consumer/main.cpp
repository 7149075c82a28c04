// Uses an installed sweepcdt through find_package(sweepcdt): builds a CDT and validates it.
#include <cstdio>

#include "sweepcdt/cdt.h"
#include "sweepcdt/validate.h"

int main() {
  sweepcdt::Plc<3> plc;
  plc.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1, 0.5, 0.25, 0.125};
  const auto tri = sweepcdt::cdt(plc);
  std::printf("%s\n", sweepcdt::validate(tri, plc).ok() ? "valid" : "INVALID");
}
