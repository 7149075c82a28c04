#include "gui_probe.h"

#include <QApplication>
#include <QFile>
#include <QGLWidget>
#include <QGuiApplication>
#include <QImage>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPixmap>
#include <QPushButton>
#include <QScreen>
#include <QTextStream>
#include <QTimer>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>

#include <cstdio>
#include <cstdlib>

namespace {

const char kFilter[] = "Tetrahedralize (constrained Delaunay)";
const char kNewLayer[] = "tetrahedra (cut-away)";

QMainWindow* main_window() {
  for (QWidget* w : QApplication::topLevelWidgets())
    if (auto* m = qobject_cast<QMainWindow*>(w); m != nullptr && m->isVisible()) return m;
  return nullptr;
}

// The filter's action in Filters → <submenu>, and that path.
QAction* find_filter(QMainWindow* window, QString& path) {
  for (QAction* top : window->menuBar()->actions()) {
    if (top->menu() == nullptr || top->text().remove('&') != "Filters") continue;
    for (QAction* sub : top->menu()->actions()) {
      if (sub->menu() == nullptr) continue;
      for (QAction* a : sub->menu()->actions())
        if (a->text().remove('&') == kFilter) {
          path = "Filters/" + sub->text().remove('&') + "/" + a->text();
          return a;
        }
    }
  }
  return nullptr;
}

bool layer_listed(QMainWindow* window, const QString& layer) {
  for (QTreeWidget* tree : window->findChildren<QTreeWidget*>())
    for (int column = 0; column < tree->columnCount(); ++column)
      if (!tree->findItems(layer, Qt::MatchContains | Qt::MatchRecursive, column).isEmpty()) return true;
  return false;
}

QGLWidget* view_of(QMainWindow* window) {  // MeshLab's 3D view: class GLArea, a QGLWidget
  for (QGLWidget* w : window->findChildren<QGLWidget*>())
    if (w->inherits("GLArea") && w->isVisible()) return w;
  return nullptr;
}

QPushButton* visible_button(const QString& text) {
  for (QWidget* top : QApplication::topLevelWidgets())
    for (QPushButton* b : top->findChildren<QPushButton*>())
      if (b->isVisible() && b->text().remove('&') == text) return b;
  return nullptr;
}

// One line per step in trace.txt beside probe.txt: where a hung run stopped.
void trace(const QString& line) {
  QFile out(QString::fromLocal8Bit(qgetenv("SWEEPCDT_PROBE_DIR")) + "/trace.txt");
  if (out.open(QIODevice::Append | QIODevice::Text)) QTextStream(&out) << line << "\n";
}

}  // namespace

GuiProbePlugin::GuiProbePlugin() {
  typeList << 0;
  actionList << new QAction(filterName(0), this);
  // Starts once MeshLab's event loop runs (plugins are loaded while the main window is built).
  if (!qgetenv("SWEEPCDT_PROBE_DIR").isEmpty()) QTimer::singleShot(0, this, [this] { poll(); });
}

// Not a wait for time: a look at the window's state each time the event loop comes round, until the
// state the next step needs is there (meshes given on the command line load after the window shows;
// the layer list is refreshed after a filter returns). The test's hang guard bounds it.
void GuiProbePlugin::poll() {
  const auto again = [this] { QTimer::singleShot(20, this, [this] { poll(); }); };
  QMainWindow* window = main_window();
  QGLWidget* view = window ? view_of(window) : nullptr;
  if (window == nullptr || view == nullptr) return again();
  for (QWidget* top : QApplication::topLevelWidgets())  // the filter failed: MeshLab shows a warning
    if (auto* box = qobject_cast<QMessageBox*>(top); box != nullptr && box->isVisible())
      return finish("message " + box->text().simplified() + "\n", 1);

  if (stage_ == 0) {
    if (!layer_listed(window, QString::fromLocal8Bit(qgetenv("SWEEPCDT_PROBE_LAYER")))) return again();
    QAction* filter = find_filter(window, menu_path_);
    if (filter == nullptr) return finish("menu \n", 1);
    stage_ = 1;
    trace("input layer listed; triggering " + menu_path_);
    filter->trigger();  // opens the filter's parameter dialog
    return again();
  }
  if (stage_ == 1) {
    QPushButton* apply = visible_button("Apply");
    if (apply == nullptr) return again();
    stage_ = 2;
    trace("pressing Apply");
    apply->click();
    trace("Apply returned");  // runs the filter with the dialog's defaults
    return again();
  }
  if (!layer_listed(window, kNewLayer)) {
    if (stage_ == 2) {  // once: what the layer list shows
      stage_ = 3;
      QString all;
      for (QTreeWidget* tree : window->findChildren<QTreeWidget*>())
        for (QTreeWidgetItemIterator it(tree); *it; ++it)
          for (int c = 0; c < (*it)->columnCount(); ++c) all += " [" + (*it)->text(c) + "]";
      trace("waiting for the new layer; the layer list shows:" + all);
    }
    return again();
  }

  QString report = "window " + window->windowTitle() + "\nmenu " + menu_path_ + "\nlayer " + kNewLayer + "\n";
  // Paint now (repaint() is synchronous: MeshLab draws and swaps), then read the view's window back
  // from the X server, where the frame now is.
  view->repaint();
  QApplication::sync();
  const QImage image = QGuiApplication::primaryScreen()->grabWindow(view->winId()).toImage();
  const QString dir = QString::fromLocal8Bit(qgetenv("SWEEPCDT_PROBE_DIR"));
  report += QString("screenshot %1x%2 %3\n").arg(image.width()).arg(image.height()).arg(image.save(dir + "/screenshot.png") ? "saved" : "failed");
  // Warm pixels (red clearly above blue): the cut's quality colours from red (poor) to yellow and
  // green; MeshLab's background is blue-violet and the surface grey, so neither counts.
  qint64 warm = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) warm += qRed(image.pixel(x, y)) > qBlue(image.pixel(x, y)) + 64;
  report += QString("warm %1 of %2 pixels\n").arg(warm).arg(qint64{image.width()} * image.height());
  finish(report, 0);
}

void GuiProbePlugin::finish(const QString& report, int status) {
  QFile out(QString::fromLocal8Bit(qgetenv("SWEEPCDT_PROBE_DIR")) + "/probe.txt");
  if (out.open(QIODevice::WriteOnly | QIODevice::Text)) QTextStream(&out) << report;
  out.close();
  std::fflush(nullptr);
  std::_Exit(status);  // MeshLab's own shutdown would ask whether to save the project
}

MESHLAB_PLUGIN_NAME_EXPORTER(GuiProbePlugin)
