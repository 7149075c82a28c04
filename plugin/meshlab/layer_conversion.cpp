#include "layer_conversion.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/selection.h>

#include <unordered_map>

namespace sweepcdt::meshlab {

void read_layer(const CMeshO& mesh, JobInput& input, std::vector<CMeshO::FacePointer>& faces) {
  std::unordered_map<const CVertexO*, uint32_t> id;
  id.reserve(mesh.vert.size());
  input.points.clear();
  for (const CVertexO& v : mesh.vert) {
    if (v.IsD()) continue;
    id.emplace(&v, static_cast<uint32_t>(input.points.size() / 3));
    for (int k = 0; k < 3; ++k) input.points.push_back(static_cast<double>(v.cP()[k]));  // float -> double: exact
  }
  input.triangles.clear();
  faces.clear();
  for (const CFaceO& f : mesh.face) {
    if (f.IsD()) continue;
    for (int k = 0; k < 3; ++k) input.triangles.push_back(id.at(f.cV(k)));
    faces.push_back(const_cast<CMeshO::FacePointer>(&f));
  }
}

void select_faces(CMeshO& mesh, const std::vector<CMeshO::FacePointer>& faces, const std::vector<uint32_t>& triangles) {
  vcg::tri::UpdateSelection<CMeshO>::FaceClear(mesh);
  for (uint32_t t : triangles)
    if (t < faces.size()) faces[t]->SetS();
}

namespace {

vcg::Color4b region_colour(int32_t region) {
  static const vcg::Color4b palette[] = {{230, 159, 0, 255},   {86, 180, 233, 255}, {0, 158, 115, 255}, {240, 228, 66, 255},
                                         {0, 114, 178, 255},   {213, 94, 0, 255},   {204, 121, 167, 255}};
  return palette[static_cast<unsigned>(region) % (sizeof palette / sizeof palette[0])];
}

}  // namespace

void fill_cut_away_layer(MeshModel& layer, const JobResult& result, Colouring colouring) {
  CMeshO& m = layer.cm;
  layer.updateDataMask(MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY);
  const std::size_t n = result.points.size() / 3, t = result.triangles.size() / 3;
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, n);
  std::vector<CMeshO::VertexPointer> vertex(n);
  for (std::size_t v = 0; v < n; ++v, ++vi) {
    vertex[v] = &*vi;
    // Display only: MeshLab's layers hold floats (the exact coordinates are in the volume file).
    vi->P() = CMeshO::CoordType(static_cast<float>(result.points[3 * v]), static_cast<float>(result.points[3 * v + 1]),
                                static_cast<float>(result.points[3 * v + 2]));
  }
  auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(m, t);
  for (std::size_t f = 0; f < t; ++f, ++fi) {
    for (int k = 0; k < 3; ++k) fi->V(k) = vertex[result.triangles[3 * f + k]];
    fi->Q() = static_cast<float>(result.quality[f]);
    if (!result.on_cut[f]) fi->C() = vcg::Color4b(200, 200, 200, 255);
    else if (colouring == Colouring::Region) fi->C() = region_colour(result.region[f]);
    else fi->C().SetColorRamp(0.0f, 1.0f, static_cast<float>(result.quality[f]));
  }
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(m);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalized(m);
}

}  // namespace sweepcdt::meshlab
