// cdt(): check the PLC, run the chosen algorithm, pair neighbours, assign regions — and verify the
// result before returning it: a PLC without a CDT must fail with NoCdtError, never return a wrong
// triangulation.
#include "sweepcdt/cdt.h"

#include "gift_wrap.h"
#include "regions.h"
#include "sweepcdt/validate.h"

namespace sweepcdt {

template <int D>
Triangulation<D> cdt(const Plc<D>& plc, const Options& options) {
  check(plc);
  Triangulation<D> tri = detail::gift_wrap(plc, options);
  compute_neighbors(tri);
  detail::assign_regions(tri, plc);
  const ValidationReport report = validate(tri, plc);
  if (!report.ok())
    throw NoCdtError("no CDT: the constructed triangulation fails validation (" + report.failures.front().check + ": " +
                         report.failures.front().detail + ")",
                     {});
  return tri;
}

template Triangulation<2> cdt<2>(const Plc<2>&, const Options&);
template Triangulation<3> cdt<3>(const Plc<3>&, const Options&);
template Triangulation<4> cdt<4>(const Plc<4>&, const Options&);
template Triangulation<5> cdt<5>(const Plc<5>&, const Options&);

}  // namespace sweepcdt
