// A test-only MeshLab plugin for the GUI smoke test (issue 15), never installed: loaded with the
// filter into a private MeshLab tree, it drives MeshLab's own GUI from inside its event loop, as a
// user would — once the main window lists the input layer, it finds "Tetrahedralize (constrained
// Delaunay)" in Filters → Remeshing, Simplification and Reconstruction, triggers it, presses Apply
// in the parameter dialog (the defaults), waits for the cut-away layer to be listed, then writes
// what it saw to probe.txt and a screenshot of the 3D view to screenshot.png, and ends the process.
// Environment: SWEEPCDT_PROBE_DIR (where to write), SWEEPCDT_PROBE_LAYER (the input layer's name).
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
  QString filterInfo(FilterIDType) const override { return "Test only: drives the Tetrahedralize filter and takes a screenshot."; }
  FilterClass getClass(QAction*) override { return MeshFilterInterface::Measure; }
  FILTER_ARITY filterArity(QAction*) const override { return SINGLE_MESH; }
  int getPreConditions(QAction*) const override { return MeshModel::MM_NONE; }
  int postCondition(QAction*) const override { return MeshModel::MM_NONE; }
  bool applyFilter(QAction*, MeshDocument&, const RichParameterList&, vcg::CallBackPos*) override { return true; }

 private:
  void poll();
  void finish(const QString& report, int status);
  int stage_ = 0;  // 0: wait for the input layer; 1: for the dialog; 2, 3: for the new layer
  QString menu_path_;
};
