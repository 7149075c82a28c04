"""The Tetrahedralize command of the SweepCDT workbench: a task panel sets the options (algorithm,
Steiner mode, facets, deflection), runs sweepcdt_femmesh.tetrahedralize_object on the selected
solid and shows the result; failures go to the report view, and FreeCAD keeps running."""

import FreeCAD
import FreeCADGui
from PySide import QtGui

import sweepcdt_femmesh
from sweepcdt_paths import ICON


def selected_solid():
    """The selected Part feature with a solid, or Mesh feature; None if there is none."""
    for obj in FreeCADGui.Selection.getSelection():
        if obj.isDerivedFrom("Mesh::Feature") or (hasattr(obj, "Shape") and not obj.Shape.isNull() and obj.Shape.Solids):
            return obj
    return None


def active_analysis():
    try:
        import FemGui
        return FemGui.getActiveAnalysis()
    except Exception:  # FEM GUI not available: the mesh goes to the document only
        return None


class TetrahedralizePanel:
    """Task panel: options, Run (OK), and the result of the last run."""

    def __init__(self, obj):
        self.obj = obj
        self.mesh_obj = None
        self.message = ""  # the last run's result or error (the label goes with the closed dialog)
        self.form = QtGui.QWidget()
        self.form.setWindowTitle(f"Tetrahedralize {obj.Label}")
        layout = QtGui.QFormLayout(self.form)
        d = sweepcdt_femmesh.DEFAULTS
        self.algorithm = self._combo(list(sweepcdt_femmesh.ALGORITHMS), d["algorithm"])
        self.steiner = self._combo(["auto", "none"], d["steiner"])
        self.facets = self._combo(["coplanar", "triangles"], d["facets"])
        self.deflection = QtGui.QDoubleSpinBox()
        self.deflection.setDecimals(3)
        self.deflection.setRange(0.001, 100.0)
        self.deflection.setSingleStep(0.05)
        self.deflection.setValue(d["deflection"])
        self.deflection.setSuffix(" mm")
        self.deflection.setEnabled(not obj.isDerivedFrom("Mesh::Feature"))
        self.result = QtGui.QLabel("")
        self.result.setWordWrap(True)
        layout.addRow("Algorithm", self.algorithm)
        layout.addRow("Steiner points", self.steiner)
        layout.addRow("Facets", self.facets)
        layout.addRow("Deflection (Part)", self.deflection)
        layout.addRow(self.result)

    @staticmethod
    def _combo(values, current):
        c = QtGui.QComboBox()
        c.addItems(values)
        c.setCurrentIndex(values.index(current))
        return c

    def options(self):
        return {"algorithm": self.algorithm.currentText(), "steiner": self.steiner.currentText(),
                "facets": self.facets.currentText(), "deflection": self.deflection.value()}

    def run(self):
        """Meshes with the panel's options; True on success. Errors are reported, never raised."""
        # FreeCAD's progress bar in the status bar; Esc aborts it (next() raises), and returning
        # False cancels the computation cleanly (sweepcdt.CancelledError, reported as a failure).
        indicator = FreeCAD.Base.ProgressIndicator()
        indicator.start(f"Tetrahedralizing {self.obj.Label}...", 0)

        def progress(phase, done, total):
            try:
                indicator.next(True)
            except Exception:
                return False
            return True

        try:
            self.mesh_obj, result, seconds = sweepcdt_femmesh.tetrahedralize_object(
                self.obj, analysis=active_analysis(), progress=progress, **self.options())
        except sweepcdt_femmesh.SweepCDTError as e:
            FreeCAD.Console.PrintError(f"SweepCDT: {e}\n")
            self.message = f"Failed: {e}"
            self.result.setText(self.message)
            return False
        except Exception as e:  # anything else: report, keep FreeCAD running
            FreeCAD.Console.PrintError(f"SweepCDT: internal error: {e!r}\n")
            self.message = f"Internal error: {e!r}"
            self.result.setText(self.message)
            return False
        finally:
            indicator.stop()
        text = sweepcdt_femmesh.summary(result, seconds)
        FreeCAD.Console.PrintMessage(f"SweepCDT: {self.obj.Label} -> {self.mesh_obj.Label}: {text}\n")
        self.message = text
        self.result.setText(text)
        return True

    def accept(self):
        if self.run():
            FreeCADGui.Control.closeDialog()
            if self.mesh_obj is not None:
                self.obj.ViewObject.Visibility = False
        return True

    def reject(self):
        FreeCADGui.Control.closeDialog()
        return True


class TetrahedralizeCommand:
    def GetResources(self):
        return {"Pixmap": ICON, "MenuText": "Tetrahedralize",
                "ToolTip": "Tetrahedralize the selected solid (Part feature, or closed Mesh feature) into a FEM mesh, "
                           "exactly (constrained Delaunay); inside the active analysis if there is one"}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and selected_solid() is not None

    def Activated(self):
        obj = selected_solid()
        if obj is None:
            FreeCAD.Console.PrintError("SweepCDT: select a Part feature with a solid, or a closed Mesh feature\n")
            return
        global last_panel
        last_panel = TetrahedralizePanel(obj)
        FreeCADGui.Control.showDialog(last_panel)


#: The panel the command opened last (for scripts and the GUI test).
last_panel = None

FreeCADGui.addCommand("SweepCDT_Tetrahedralize", TetrahedralizeCommand())
