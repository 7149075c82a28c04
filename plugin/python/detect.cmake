# Included by the root CMakeLists.txt: finds what the Python module needs — Debian's /usr/bin/python3
# (the interpreter FreeCAD 0.20 embeds; a pyenv or venv python earlier on PATH would build a module
# FreeCAD cannot load) with numpy, and pybind11 (Debian pybind11-dev) — and sets
# SWEEPCDT_PYTHON_FOUND.
set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "the Python the module is built for (FreeCAD's)")
find_package(Python 3.8 COMPONENTS Interpreter Development.Module NumPy QUIET)
if(Python_FOUND)
  set(PYBIND11_FINDPYTHON ON)
  find_package(pybind11 2.6 CONFIG QUIET)
endif()
set(SWEEPCDT_PYTHON_FOUND FALSE)
if(Python_FOUND AND Python_NumPy_FOUND AND pybind11_FOUND)
  set(SWEEPCDT_PYTHON_FOUND TRUE)
endif()
