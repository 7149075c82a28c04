// A test-only MeshLab plugin for the GUI smoke test (issue 15), never installed: loaded with the
// filter into a private MeshLab tree, it waits inside MeshLab's event loop until the main window
// shows the expected layer, then writes what it found (is "Tetrahedralize (constrained Delaunay)" in
// Filters → Remeshing, Simplification and Reconstruction?) and a screenshot of the 3D view, and
// ends the process. Driven by SWEEPCDT_PROBE_DIR (where to write probe.txt and screenshot.png) and
// SWEEPCDT_PROBE_LAYER (a layer name the layer list must show first).
#pragma once
#include <common/interfaces.h>

class GuiProbePlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

 public:
  GuiProbePlugin();
  QString pluginName() const override { return "SweepCdtGuiProbe"; }
  QString filterName(FilterIDType) const override { return "sweepcdt GUI test probe"; }
  QString filterInfo(FilterIDType) const override { return "Test only: records the menus and a screenshot."; }
  FilterClass getClass(QAction*) override { return MeshFilterInterface::Measure; }
  FILTER_ARITY filterArity(QAction*) const override { return SINGLE_MESH; }
  int getPreConditions(QAction*) const override { return MeshModel::MM_NONE; }
  int postCondition(QAction*) const override { return MeshModel::MM_NONE; }
  bool applyFilter(QAction*, MeshDocument&, const RichParameterList&, vcg::CallBackPos*) override { return true; }

 private:
  void poll();
};
