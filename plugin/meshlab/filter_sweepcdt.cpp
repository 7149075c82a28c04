#include "filter_sweepcdt.h"

#include <QFileInfo>

#include <exception>
#include <new>
#include <vector>

#include "job.h"
#include "layer_conversion.h"

using sweepcdt::meshlab::Choices;
using sweepcdt::meshlab::JobInput;
using sweepcdt::meshlab::JobResult;

namespace {

QStringList list_of(const std::vector<std::string>& words) {
  QStringList list;
  for (const std::string& w : words) list << QString::fromStdString(w);
  return list;
}

}  // namespace

FilterSweepCdtPlugin::FilterSweepCdtPlugin() {
  typeList << FP_TETRAHEDRALIZE;
  for (FilterIDType id : types()) actionList << new QAction(filterName(id), this);
}

QString FilterSweepCdtPlugin::pluginName() const { return "FilterSweepCdt"; }

QString FilterSweepCdtPlugin::filterName(FilterIDType) const { return "Tetrahedralize (constrained Delaunay)"; }

QString FilterSweepCdtPlugin::filterInfo(FilterIDType) const {
  return "Fills the closed surface of the current layer with tetrahedra: its exact <b>constrained Delaunay "
         "tetrahedralization</b> (sweepcdt, after J. R. Shewchuk, <i>Sweep Algorithms for Constructing "
         "Higher-Dimensional Constrained Delaunay Triangulations</i>), written to a volume mesh file whose extension "
         "picks the format: <tt>.mesh</tt> (Medit), <tt>.vtu</tt> (VTK/ParaView), <tt>.msh</tt> (Gmsh 4.1), "
         "<tt>.node</tt> (TetGen .node/.ele/.face), <tt>.inp</tt> (Abaqus/CalculiX). The layer's float coordinates are "
         "used exactly; every triangle becomes a boundary facet of the mesh.<br><br>"
         "MeshLab shows surfaces only, so the filter adds a <b>cut-away layer</b>: the tetrahedra whose centroid lies "
         "below a plane across the chosen axis, drawn as the triangles that bound them. Faces on the cut show the "
         "interior elements, coloured by element quality (radius ratio 3r/R: red = poor, blue = good; also stored as "
         "face quality) or by region (separate bodies); faces on the surface are grey. The surface layer is hidden so "
         "that the cut can be seen (the eye in the layer list shows it again). Move the plane to look inside.<br><br>"
         "A layer that does not bound a volume (open, non-manifold, degenerate, duplicate or self-intersecting faces) "
         "is refused with a message naming the problems, and <b>the offending faces are selected</b> in the layer: "
         "repair them with Filters &rarr; Cleaning and Repairing and run the filter again.<br><br>"
         "Steiner mode <i>auto</i> adds points on the surface edges where the surface has no CDT as given (most real "
         "surfaces); <i>none</i> keeps the surface exactly. Facets <i>coplanar</i> merges exactly coplanar neighbouring "
         "triangles into one facet (fewer Steiner points). A snap tolerance above 0 first rounds coordinates that differ "
         "by less than it (relative to the bounding-box diagonal) to one value: a repair for CAD rounding noise, as "
         "<tt>sweepcdt --snap</tt>. Verify validates the result once more, exactly, before writing.";
}

MeshFilterInterface::FilterClass FilterSweepCdtPlugin::getClass(QAction*) { return MeshFilterInterface::Remeshing; }

MeshFilterInterface::FILTER_ARITY FilterSweepCdtPlugin::filterArity(QAction*) const { return SINGLE_MESH; }

int FilterSweepCdtPlugin::getPreConditions(QAction*) const { return MeshModel::MM_FACENUMBER; }

// The input layer's face selection changes (on bad input); the new layer is a new mesh.
int FilterSweepCdtPlugin::postCondition(QAction*) const { return MeshModel::MM_FACEFLAGSELECT; }

void FilterSweepCdtPlugin::initParameterSet(QAction*, MeshModel& m, RichParameterList& par) {
  const Choices c = sweepcdt::meshlab::choices();
  QFileInfo layer(m.fullName());
  QString base = layer.completeBaseName().isEmpty() ? m.label() : layer.completeBaseName();
  if (base.isEmpty()) base = "tetrahedra";
  const QString dir = layer.absolutePath().isEmpty() || m.fullName().isEmpty() ? QString(".") : layer.absolutePath();
  par.addParam(RichSaveFile("OutputFile", dir + "/" + base + ".mesh", ".mesh", "Output volume mesh",
                            "The file to write; its extension picks the format: .mesh (Medit), .vtu (VTK), .msh (Gmsh 4.1), "
                            ".node (TetGen .node/.ele/.face), .inp (Abaqus/CalculiX)."));
  par.addParam(RichEnum("Algorithm", c.default_algorithm, list_of(c.algorithms), "Algorithm",
                        "sweep-sphere (default), sweep-plane, or giftwrap (slow; the reference)."));
  par.addParam(RichEnum("Steiner", c.default_steiner, list_of(c.steiner), "Steiner points",
                        "auto: add points on surface edges where the surface has no CDT as given; none: the surface exactly "
                        "(fails when it has no CDT)."));
  par.addParam(RichEnum("Facets", c.default_facets, list_of(c.facets), "Facets",
                        "triangles: each triangle is a facet; coplanar: exactly coplanar neighbouring triangles form one facet."));
  par.addParam(RichString("Snap", "0", "Snap tolerance",
                          "0: exact input. Above 0 (at most 1e-3, relative to the bounding-box diagonal, e.g. 1e-12): round "
                          "coordinates closer than this to one value first (CAD rounding noise)."));
  par.addParam(RichBool("Verify", false, "Verify", "Validate the result once more, exactly, before writing it."));
  // z: MeshLab's initial view looks down the z axis, so the cut faces the user.
  par.addParam(RichEnum("CutAxis", 2, list_of(c.axes), "Cut-away axis",
                        "The axis across which the display plane cuts (z faces MeshLab's initial view)."));
  par.addParam(RichDynamicFloat("CutPosition", 0.5f, 0.0f, 1.0f, "Cut-away position",
                                "Where the plane cuts, as a fraction of the mesh's extent along the axis (1 shows every tetrahedron)."));
  par.addParam(RichEnum("Colour", 0, list_of(c.colourings), "Colour the cut by",
                        "element quality (radius ratio: red poor, blue good) or region (separate bodies)."));
}

bool FilterSweepCdtPlugin::applyFilter(QAction* action, MeshDocument& md, const RichParameterList& par, vcg::CallBackPos* cb) {
  // Nothing may escape into MeshLab: every failure becomes errorMessage.
  try {
    switch (ID(action)) {
      case FP_TETRAHEDRALIZE: return tetrahedralize(md, par, cb);
      default: errorMessage = "unknown filter"; return false;
    }
  } catch (const std::bad_alloc&) {
    errorMessage = "Tetrahedralize: out of memory";
  } catch (const std::exception& e) {
    errorMessage = QString("Tetrahedralize: internal error: ") + e.what();
  } catch (...) {
    errorMessage = "Tetrahedralize: internal error: unknown exception";
  }
  Log("%s", qUtf8Printable(errorMessage));
  return false;
}

bool FilterSweepCdtPlugin::tetrahedralize(MeshDocument& md, const RichParameterList& par, vcg::CallBackPos* cb) {
  MeshModel* source = md.mm();
  if (source == nullptr) {
    errorMessage = "Tetrahedralize: no current layer";
    return false;
  }
  JobInput in;
  in.name = qUtf8Printable(source->label());
  in.output = qUtf8Printable(par.getSaveFileName("OutputFile"));
  in.algorithm = par.getEnum("Algorithm");
  in.steiner = par.getEnum("Steiner");
  in.facets = par.getEnum("Facets");
  in.snap = qUtf8Printable(par.getString("Snap").trimmed());
  in.verify = par.getBool("Verify");
  in.cut_axis = par.getEnum("CutAxis");
  in.cut_fraction = par.getDynamicFloat("CutPosition");
  if (cb) in.progress = [cb](int percent, const char* phase) { cb(percent, phase); };
  std::vector<CMeshO::FacePointer> faces;
  sweepcdt::meshlab::read_layer(source->cm, in, faces);

  const JobResult r = sweepcdt::meshlab::run_job(in);
  if (!r.ok) {
    if (!r.select.empty()) {
      source->updateDataMask(MeshModel::MM_FACEFLAGSELECT);
      sweepcdt::meshlab::select_faces(source->cm, faces, r.select);
    }
    errorMessage = QString::fromStdString(r.error);
    Log("Tetrahedralize failed: %s", r.error.c_str());
    for (const std::string& line : r.details) {
      errorMessage += "<br>" + QString::fromStdString(line).toHtmlEscaped();
      Log("  %s", line.c_str());
    }
    return false;
  }
  for (const std::string& line : r.log) Log("%s", line.c_str());
  // The surface would hide the cut inside it: hide it (the eye in the layer list shows it again).
  source->visible = false;
  // MeshLab's layer list shows a label up to its last dot: "spot.stl" gives "spot tetrahedra (cut-away)".
  QString base = QFileInfo(source->label()).completeBaseName();
  base.replace('.', '_');
  MeshModel* layer = md.addNewMesh("", base + " tetrahedra (cut-away)", false);
  sweepcdt::meshlab::fill_cut_away_layer(*layer, r,
                                          par.getEnum("Colour") == 1 ? sweepcdt::meshlab::Colouring::Region : sweepcdt::meshlab::Colouring::Quality);
  return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterSweepCdtPlugin)
