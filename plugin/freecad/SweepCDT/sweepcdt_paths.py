"""Where the workbench's files are: FreeCAD runs Init.py/InitGui.py without __file__, and the icon
must be found even when the sweepcdt module is not installed (the workbench then says so)."""
import os

ICON = os.path.join(os.path.dirname(os.path.abspath(__file__)), "Resources", "icons", "SweepCDT.svg")
