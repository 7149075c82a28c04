# SweepCDT workbench, GUI part (loaded by the FreeCAD GUI only): one command, Tetrahedralize, in a
# toolbar and a menu. The command lives in sweepcdt_gui.py, its logic in sweepcdt_femmesh.py.
import FreeCAD
import FreeCADGui


class SweepCDTWorkbench(FreeCADGui.Workbench):
    MenuText = "SweepCDT"
    ToolTip = "Exact constrained Delaunay tetrahedralization of solids into FEM meshes (sweepcdt)"
    # An icon file, not an inline XPM: a malformed XPM crashes FreeCAD 0.20's start page (HOSTS.md 1.2).
    Icon = ""  # set below from sweepcdt_paths (InitGui.py runs without __file__)

    def Initialize(self):
        try:
            import sweepcdt_gui  # registers the command
        except ImportError as e:
            # Without the module (not installed for /usr/bin/python3) the workbench shows no command;
            # say why in the report view instead of failing the activation.
            FreeCAD.Console.PrintError(f"SweepCDT: {e}: install sweepcdt's Python module (see its README)\n")
            return
        self.appendToolbar("SweepCDT", ["SweepCDT_Tetrahedralize"])
        self.appendMenu("SweepCDT", ["SweepCDT_Tetrahedralize"])

    def Activated(self):
        pass

    def Deactivated(self):
        pass

    def GetClassName(self):
        return "Gui::PythonWorkbench"


import sweepcdt_paths  # in this folder, which FreeCAD put on sys.path

SweepCDTWorkbench.Icon = sweepcdt_paths.ICON
FreeCADGui.addWorkbench(SweepCDTWorkbench())
