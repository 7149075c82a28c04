// The Delaunay tetrahedralization of a surface's points, computed on a helper thread while the
// surface is checked (find_problems_before_cdt, plc.cpp: importers call it), and kept in the check's
// record (PlcCheck) until cdt() takes it (Steiner refinement starts from it, steiner/refine.cpp,
// and without refinement the cavity sweep, cdt.cpp). On a small flat CAD part the check and the
// tetrahedralization each took about a third of the run, one after the other. The
// tetrahedralization is a pure function of the points (delaunay.h), so taking it changes nothing
// but the time; a record never taken stops its helper when it is destroyed.
#pragma once
#include <memory>
#include <mutex>
#include <vector>

#include "sweepcdt/plc.h"
#include "in_background.h"

namespace sweepcdt::detail {

struct KeptTetrahedralization {
  explicit KeptTetrahedralization(std::vector<double> p)
      : points(std::move(p)), helper([this](const auto& inserted) { return std::make_unique<DelaunayEdges>(points, inserted); }) {}
  std::vector<double> points;  // first: the helper reads them from the start
  std::mutex mutex;
  bool taken = false;
  InBackground<std::unique_ptr<DelaunayEdges>> helper;
};

// What core's internals reach in a PlcCheck (sweepcdt/plc.h).
struct PlcCheckAccess {
  template <int D>
  static std::shared_ptr<const PlcCheck<D>> make(const Plc<D>& plc, std::shared_ptr<KeptTetrahedralization> kept) {
    return std::shared_ptr<const PlcCheck<D>>(new PlcCheck<D>(plc.points, plc.simplices, std::move(kept)));
  }
  static const std::shared_ptr<KeptTetrahedralization>& kept(const PlcCheck<3>& check) { return check.kept_; }
};

// Stops the helper of a tetrahedralization nobody will take (one already claimed goes on).
inline void drop(KeptTetrahedralization& kept) {
  std::lock_guard lock(kept.mutex);
  if (kept.taken) return;
  kept.taken = true;
  kept.helper.stop();
}

// Stops the helper of the tetrahedralization plc's record keeps, if any and not claimed: cdt() will
// not use it (neither Steiner refinement nor the cavity sweep runs, or the run is over).
inline void drop_kept_tetrahedralization(const Plc<3>& plc) {
  if (plc.checked && PlcCheckAccess::kept(*plc.checked)) drop(*PlcCheckAccess::kept(*plc.checked));
}

// The kept tetrahedralization of plc's points, claimed once (null after that, or when plc carries
// none, or a record that does not cover it: then its helper is stopped), without waiting for it, so
// that the caller can do other work meanwhile (refinement groups the facets), then wait_for_claimed().
inline std::shared_ptr<KeptTetrahedralization> claim_kept_tetrahedralization(const Plc<3>& plc) {
  if (!plc.checked || !PlcCheckAccess::kept(*plc.checked)) return nullptr;
  const std::shared_ptr<KeptTetrahedralization>& kept = PlcCheckAccess::kept(*plc.checked);
  if (!plc.checked->covers(plc)) {
    drop(*kept);
    return nullptr;
  }
  std::lock_guard lock(kept->mutex);
  if (kept->taken) return nullptr;
  kept->taken = true;
  return kept;
}

// A claimed tetrahedralization: waits for the helper meanwhile calling report(inserted) (false: stop
// it and return null, the caller cancels); null also when the helper found none. The result reads
// the record's copy of the points: rebind it (DelaunayEdges::rebind) to the caller's own before the
// record can go.
template <class Report>
std::unique_ptr<DelaunayEdges> wait_for_claimed(KeptTetrahedralization& claimed, Report&& report) {
  std::unique_ptr<DelaunayEdges>* made = claimed.helper.get(report);
  return made ? std::move(*made) : nullptr;
}

// Both at once.
template <class Report>
std::unique_ptr<DelaunayEdges> take_kept_tetrahedralization(const Plc<3>& plc, Report&& report) {
  const std::shared_ptr<KeptTetrahedralization> claimed = claim_kept_tetrahedralization(plc);
  return claimed ? wait_for_claimed(*claimed, report) : nullptr;
}

}  // namespace sweepcdt::detail
