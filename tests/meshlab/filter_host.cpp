// A minimal MeshLab host for the selection test (issue 15): meshlabserver exits as soon as a filter
// fails, without saving anything, so the faces the failing filter selected can only be seen from
// inside the process. This program does what meshlabserver does with our filter — loads the plugin
// with QPluginLoader, reads a mesh into a MeshDocument layer (vcglib's OFF/STL importers, as
// MeshLab's own io plugin uses), fills the filter's parameters, applies it — and then prints what the
// layer looks like: the result, the error message, the log and the selected face indices.
//
// Usage: filter_host PLUGIN.so INPUT.{off,stl} OUTPUT.mesh [ENUM_PARAMETER=INDEX ...]
// Prints:  result ok|failed / error <message> / log <line>... / faces <n> / selected <i j k ...>
#include <common/interfaces.h>
#include <common/GLLogStream.h>
#include <wrap/gl/glu_tessellator_cap.h>  // import_off.h triangulates polygons with it
#include <wrap/io_trimesh/import_off.h>
#include <wrap/io_trimesh/import_stl.h>

#include <QApplication>
#include <QPluginLoader>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: filter_host PLUGIN.so INPUT.{off,stl} OUTPUT.mesh [ENUM_PARAMETER=INDEX ...]\n");
    return 2;
  }
  QApplication app(argc, argv);
  QPluginLoader loader(argv[1]);
  QObject* instance = loader.instance();
  auto* filter = qobject_cast<MeshFilterInterface*>(instance);
  if (filter == nullptr) {
    std::fprintf(stderr, "cannot load %s as a MeshLab filter: %s\n", argv[1], qUtf8Printable(loader.errorString()));
    return 1;
  }
  MeshDocument md;
  MeshModel* layer = md.addNewMesh(argv[2], "layer", true);
  const QString input(argv[2]);
  int mask = 0, err = 0;
  if (input.endsWith(".off", Qt::CaseInsensitive)) err = vcg::tri::io::ImporterOFF<CMeshO>::Open(layer->cm, argv[2], mask);
  else err = vcg::tri::io::ImporterSTL<CMeshO>::Open(layer->cm, argv[2], mask);
  if (err != 0 || layer->cm.fn == 0) {
    std::fprintf(stderr, "cannot read %s (error %d)\n", argv[2], err);
    return 1;
  }
  GLLogStream log;
  filter->setLog(&log);
  QAction* action = filter->actions().at(0);
  RichParameterList parameters;
  filter->initParameterSet(action, md, parameters);
  parameters.setValue("OutputFile", FileValue(argv[3]));
  for (int i = 4; i < argc; ++i) {  // e.g. Steiner=1 (none)
    const QStringList nv = QString(argv[i]).split('=');
    if (nv.size() != 2 || !parameters.hasParameter(nv[0])) {
      std::fprintf(stderr, "bad parameter %s\n", argv[i]);
      return 2;
    }
    parameters.setValue(nv[0], EnumValue(nv[1].toInt()));
  }
  const bool ok = filter->applyFilter(action, md, parameters, nullptr);

  std::printf("result %s\n", ok ? "ok" : "failed");
  if (!ok) std::printf("error %s\n", qUtf8Printable(filter->errorMsg()));
  QStringList lines;
  log.print(lines);
  for (const QString& line : lines) std::printf("log %s\n", qUtf8Printable(line));
  std::printf("faces %d\nselected", layer->cm.fn);
  int index = 0;
  for (const CFaceO& f : layer->cm.face) {
    if (f.IsD()) continue;
    if (f.IsS()) std::printf(" %d", index);
    ++index;
  }
  std::printf("\nlayers %d\n", md.meshList.size());
  return 0;
}
