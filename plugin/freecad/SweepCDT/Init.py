# SweepCDT workbench, loaded by FreeCAD (GUI and freecadcmd) at start-up: registers the volume-mesh
# formats sweepcdt writes that FreeCAD does not read itself (Medit .mesh, Gmsh .msh, TetGen .node/.ele).
# FreeCAD reads .inp, .vtu, .vtk, .unv, .z88 and .med already (Fem module), so those are left to it.
import FreeCAD

FreeCAD.addImportType("sweepcdt volume mesh: Medit, Gmsh, TetGen (*.mesh *.msh *.node *.ele)", "sweepcdt_fileformats")
FreeCAD.addExportType("sweepcdt volume mesh: Medit, Gmsh, TetGen (*.mesh *.msh *.node)", "sweepcdt_fileformats")
