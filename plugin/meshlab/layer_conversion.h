// MeshLab layers to and from the plain arrays of job.h: the layer's live vertices and faces in
// order (float coordinates widened to double, exactly), face selection, and the cut-away layer.
#pragma once
#include <common/meshmodel.h>

#include <vector>

#include "job.h"

namespace sweepcdt::meshlab {

// Fills input.points and input.triangles from the layer's vertices and faces that are not deleted;
// faces[j] is the face that became triangle j.
void read_layer(const CMeshO& mesh, JobInput& input, std::vector<CMeshO::FacePointer>& faces);

// Clears the layer's face selection, then selects faces[t] for every t in `triangles`.
void select_faces(CMeshO& mesh, const std::vector<CMeshO::FacePointer>& faces, const std::vector<uint32_t>& triangles);

enum class Colouring { Quality, Region };

// Fills `layer` with the cut-away triangles of `result`, with per-face quality (the radius ratio)
// and per-face colour: the cut faces by quality (red = poor, blue = good) or by region, the
// domain-boundary faces light grey.
void fill_cut_away_layer(MeshModel& layer, const JobResult& result, Colouring colouring);

}  // namespace sweepcdt::meshlab
