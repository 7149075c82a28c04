// soup_of_arrays() and plc_of_soup() (sweepcdt/io/surface_arrays.h): arrays get the readers' checks,
// and a soup from arrays becomes the same PLC as the file it came from.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <set>
#include <vector>

#include "delaunay/delaunay.h"
#include "delaunay/kept_tetrahedralization.h"
#include "parallel.h"
#include "surface_builders.h"
#include "sweepcdt/io/error.h"
#include "sweepcdt/io/surface_arrays.h"
#include "sweepcdt/io/to_plc.h"
#include "sweepcdt/io/write_surface.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::io {
namespace {

std::vector<int64_t> ids_of(const Soup& soup) { return {soup.triangles.begin(), soup.triangles.end()}; }

InputErrorKind kind_of_failure(const std::vector<double>& points, const std::vector<int64_t>& triangles, std::string* what) {
  try {
    soup_of_arrays(points, triangles, "arrays");
  } catch (const InputError& e) {
    *what = e.what();
    return e.kind();
  }
  ADD_FAILURE() << "no InputError";
  return InputErrorKind::Unreadable;
}

TEST(SurfaceArrays, BadArraysNameTheElement) {
  const Soup cube = testing::cube_soup();
  std::string what;
  std::vector<double> p = cube.points;
  p[3 * 5 + 1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(kind_of_failure(p, ids_of(cube), &what), InputErrorKind::NonFinite);
  EXPECT_NE(what.find("point 5"), std::string::npos) << what;

  std::vector<int64_t> t = ids_of(cube);
  t[3 * 4 + 2] = static_cast<int64_t>(cube.num_points());
  EXPECT_EQ(kind_of_failure(cube.points, t, &what), InputErrorKind::IndexOutOfRange);
  EXPECT_NE(what.find("triangle 4"), std::string::npos) << what;
  t[3 * 4 + 2] = -1;
  EXPECT_EQ(kind_of_failure(cube.points, t, &what), InputErrorKind::IndexOutOfRange);

  t = ids_of(cube);
  t.pop_back();
  EXPECT_EQ(kind_of_failure(cube.points, t, &what), InputErrorKind::SizeMismatch);
}

// The same steps as import_plc(): a soup written to a file and read back gives the same PLC.
TEST(SurfaceArrays, SamePlcAsTheFile) {
  Soup soup = testing::cube_soup();
  const auto file = std::filesystem::temp_directory_path() / "sweepcdt_surface_arrays_cube.off";
  write_surface(file, soup, Format::Off);
  const Plc<3> from_file = import_plc(file);
  std::filesystem::remove(file);
  const Plc<3> from_arrays = plc_of_soup(soup_of_arrays(soup.points, ids_of(soup), "cube"));
  EXPECT_EQ(from_arrays.points, from_file.points);
  EXPECT_EQ(from_arrays.simplices, from_file.simplices);
  EXPECT_EQ(from_arrays.exterior, from_file.exterior);
  EXPECT_EQ(from_arrays.tags, from_file.tags);
}

// A PLC imported to be meshed (for_cdt, the default) carries the Delaunay tetrahedralization of its
// points, computed beside the check on a second thread, for cdt() to take: here taken, it has the
// edges of one built from scratch. Imported only to be read (for_cdt = false), or on a machine of
// one hardware thread, it carries none.
TEST(SurfaceArrays, ImportedForCdtCarriesItsTetrahedralization) {
  const Soup soup = testing::cube_soup();
  const auto go_on = [](std::size_t) { return true; };
  Plc<3> for_cdt = plc_of_soup(soup);
  std::unique_ptr<detail::DelaunayEdges> kept = detail::take_kept_tetrahedralization(for_cdt, go_on);
  if (detail::thread_count(0) == 1) {
    EXPECT_EQ(kept, nullptr) << "one hardware thread: nothing to compute it on";
  } else {
    ASSERT_NE(kept, nullptr);
    std::vector<double> points = for_cdt.points;
    kept->rebind(points);
    for_cdt.checked.reset();
    std::set<std::pair<uint32_t, uint32_t>> edges;
    for (const auto& t : detail::delaunay_simplices<3>(points))
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) edges.insert(std::minmax(t[i], t[j]));
    for (uint32_t a = 0; a < points.size() / 3; ++a)
      for (uint32_t b = a + 1; b < points.size() / 3; ++b) EXPECT_EQ(kept->has_edge(a, b), edges.count({a, b}) > 0) << a << " " << b;
  }
  const Plc<3> read_only = plc_of_soup(soup, 0, nullptr, nullptr, /*for_cdt=*/false);
  ASSERT_TRUE(read_only.checked && read_only.checked->covers(read_only)) << "the check's record is still kept";
  EXPECT_EQ(detail::take_kept_tetrahedralization(read_only, go_on), nullptr);
}

// Welding merges equal points and drops unused ones; point_ids says where each soup point went.
TEST(SurfaceArrays, PointIdsFollowWelding) {
  Soup soup = testing::cube_soup();
  const uint32_t n = static_cast<uint32_t>(soup.num_points());
  soup.points.insert(soup.points.end(), {5.0, 5.0, 5.0});                 // point n: unused
  soup.points.insert(soup.points.end(), soup.points.begin(), soup.points.begin() + 3);  // n+1 = point 0
  for (auto& id : soup.triangles)
    if (id == 0) { id = n + 1; break; }  // one corner of point 0 now names its copy
  std::vector<uint32_t> point_ids;
  const Plc<3> plc = plc_of_soup(soup_of_arrays(soup.points, ids_of(soup), "cube"), 0, nullptr, &point_ids);
  ASSERT_EQ(point_ids.size(), n + 2u);
  EXPECT_EQ(point_ids[n], kNone);
  EXPECT_EQ(point_ids[n + 1], point_ids[0]);
  for (uint32_t i = 0; i < n + 2; ++i) {
    if (point_ids[i] == kNone) continue;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(plc.points[3 * point_ids[i] + k], soup.points[3 * i + k]) << i;
  }
}

}  // namespace
}  // namespace sweepcdt::io
