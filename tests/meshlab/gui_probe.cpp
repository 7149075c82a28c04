#include "gui_probe.h"

#include <QApplication>
#include <QGuiApplication>
#include <QPixmap>
#include <QScreen>
#include <QFile>
#include <QGLWidget>
#include <QImage>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QTextStream>
#include <QTimer>
#include <QTreeWidget>

#include <cstdio>
#include <cstdlib>

namespace {

QMainWindow* main_window() {
  for (QWidget* w : QApplication::topLevelWidgets())
    if (auto* m = qobject_cast<QMainWindow*>(w); m != nullptr && m->isVisible()) return m;
  return nullptr;
}

// "Filters/Remeshing, Simplification and Reconstruction/Tetrahedralize (constrained Delaunay)" if the
// action is there, else "".
QString find_menu_path(QMainWindow* window, const QString& action_text) {
  for (QAction* top : window->menuBar()->actions()) {
    if (top->menu() == nullptr || top->text().remove('&') != "Filters") continue;
    for (QAction* sub : top->menu()->actions()) {
      if (sub->menu() == nullptr) continue;
      for (QAction* a : sub->menu()->actions())
        if (a->text().remove('&') == action_text) return "Filters/" + sub->text().remove('&') + "/" + a->text();
    }
  }
  return {};
}

bool layer_listed(QMainWindow* window, const QString& layer) {
  for (QTreeWidget* tree : window->findChildren<QTreeWidget*>())
    if (!tree->findItems(layer, Qt::MatchContains | Qt::MatchRecursive, 1).isEmpty() ||
        !tree->findItems(layer, Qt::MatchContains | Qt::MatchRecursive, 2).isEmpty())
      return true;
  return false;
}

}  // namespace

GuiProbePlugin::GuiProbePlugin() {
  typeList << 0;
  actionList << new QAction(filterName(0), this);
  // Runs once MeshLab's event loop runs (plugins are loaded while the main window is built).
  if (!qgetenv("SWEEPCDT_PROBE_DIR").isEmpty()) QTimer::singleShot(0, this, [this] { poll(); });
}

// Not a wait for time: a check of the window's state each time the event loop comes round, until
// the layer is listed (meshes given on the command line load after the window is shown).
void GuiProbePlugin::poll() {
  QMainWindow* window = main_window();
  const QString layer = QString::fromLocal8Bit(qgetenv("SWEEPCDT_PROBE_LAYER"));
  QGLWidget* view = nullptr;  // MeshLab's 3D view, class GLArea (a QGLWidget)
  if (window != nullptr)
    for (QGLWidget* w : window->findChildren<QGLWidget*>())
      if (w->inherits("GLArea") && w->isVisible()) view = w;
  if (window == nullptr || view == nullptr || !view->isVisible() || !layer_listed(window, layer)) {
    QTimer::singleShot(20, this, [this] { poll(); });
    return;
  }
  const QString dir = QString::fromLocal8Bit(qgetenv("SWEEPCDT_PROBE_DIR"));
  QFile out(dir + "/probe.txt");
  if (out.open(QIODevice::WriteOnly | QIODevice::Text)) {
    QTextStream s(&out);
    s << "window " << window->windowTitle() << "\n";
    s << "menu " << find_menu_path(window, "Tetrahedralize (constrained Delaunay)") << "\n";
    s << "layer " << layer << "\n";
    // Paint now (repaint() is synchronous: MeshLab draws and swaps), then read the view's window back
    // from the X server, where the frame now is.
    view->repaint();
    QApplication::sync();
    const QImage image = QGuiApplication::primaryScreen()->grabWindow(view->winId()).toImage();
    s << "screenshot " << image.width() << "x" << image.height() << " " << (image.save(dir + "/screenshot.png") ? "saved" : "failed") << "\n";
    // Warm pixels (red clearly above blue): the cut's quality colours from red (poor) to yellow and
    // green; MeshLab's background is blue-violet and the surface grey, so neither counts.
    qint64 warm = 0;
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) {
        const QRgb p = image.pixel(x, y);
        warm += qRed(p) > qBlue(p) + 64;
      }
    s << "warm " << warm << " of " << qint64{image.width()} * image.height() << " pixels\n";
  }
  out.close();
  std::fflush(nullptr);
  std::_Exit(0);  // MeshLab's own shutdown would ask to save the project
}

MESHLAB_PLUGIN_NAME_EXPORTER(GuiProbePlugin)
