// The MeshLab 2020.09 filter plugin (Debian 12's MeshLab): Filters → Remeshing, Simplification and
// Reconstruction → Tetrahedralize (constrained Delaunay). MeshLab's interface only: the work is
// run_job() (job.h), through sweepcdt's io and core.
#pragma once
#include <common/interfaces.h>

class FilterSweepCdtPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

 public:
  enum { FP_TETRAHEDRALIZE };

  FilterSweepCdtPlugin();
  QString pluginName() const override;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction* action) override;
  FILTER_ARITY filterArity(QAction* action) const override;
  int getPreConditions(QAction* action) const override;
  int postCondition(QAction* action) const override;
  void initParameterSet(QAction* action, MeshModel& m, RichParameterList& parameters) override;
  bool applyFilter(QAction* action, MeshDocument& md, const RichParameterList& parameters, vcg::CallBackPos* cb) override;

 private:
  bool tetrahedralize(MeshDocument& md, const RichParameterList& parameters, vcg::CallBackPos* cb);
};
