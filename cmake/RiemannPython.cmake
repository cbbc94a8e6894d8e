# Python package `riemann`: VTK's own wrapping of every Riemann VTK module,
# plus a generated __init__.py that re-exports all classes, so that
#
#   PYTHONPATH=${RIEMANN_PYTHONPATH} /usr/bin/python3 -c "import riemann; riemann.vtkRiemannMetric()"
#
# works in the build tree, and `import riemann` works after installing to a
# prefix whose lib/python3/dist-packages is on sys.path (e.g. /usr/local).
#
# Inputs: riemann_modules (from vtk_module_scan), RIEMANN_PYTHON_DESTINATION.
# Output: RIEMANN_PYTHONPATH (cache-free; the folder that contains riemann/).

# Shared modules: Debian's /usr/bin/python3 imports extension modules, it has
# no table of built-in static VTK modules.
vtk_module_wrap_python(
  MODULES             ${riemann_modules}
  TARGET              RiemannPython
  WRAPPED_MODULES     riemann_wrapped_modules
  PYTHON_PACKAGE      riemann
  BUILD_STATIC        OFF
  # Same as Debian's python3-vtk9 (`vtkCommonCore.cpython-311-x86_64-linux-gnu.so`).
  SOABI               "${Python3_SOABI}"
  MODULE_DESTINATION  "${RIEMANN_PYTHON_DESTINATION}"
  # Gives installed modules an $ORIGIN rpath to our libraries.
  LIBRARY_DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  CMAKE_DESTINATION   "${RIEMANN_CMAKE_DESTINATION}"
  INSTALL_HEADERS     ON)

set(RIEMANN_PYTHONPATH "${CMAKE_BINARY_DIR}/${RIEMANN_PYTHON_DESTINATION}")

# __init__.py: import the VTK Python modules ours depend on first (so their
# types are registered before ours, e.g. vtkPolyDataAlgorithm as a base), then
# pull every wrapped module's classes into `riemann`.
set(_riemann_vtk_imports
  vtkmodules.vtkCommonCore
  vtkmodules.vtkCommonDataModel
  vtkmodules.vtkCommonExecutionModel)
set(_riemann_own_imports)
foreach (_riemann_module IN LISTS riemann_wrapped_modules)
  get_property(_riemann_depends GLOBAL PROPERTY "_vtk_module_${_riemann_module}_depends")
  foreach (_riemann_depend IN LISTS _riemann_depends)
    if (_riemann_depend MATCHES "^VTK::(.+)$")
      list(APPEND _riemann_vtk_imports "vtkmodules.vtk${CMAKE_MATCH_1}")
    endif ()
  endforeach ()
  get_property(_riemann_library_name GLOBAL PROPERTY "_vtk_module_${_riemann_module}_library_name")
  list(APPEND _riemann_own_imports "${_riemann_library_name}")
endforeach ()
list(REMOVE_DUPLICATES _riemann_vtk_imports)

set(RIEMANN_PYTHON_IMPORTS "")
foreach (_riemann_import IN LISTS _riemann_vtk_imports)
  string(APPEND RIEMANN_PYTHON_IMPORTS "import ${_riemann_import}  # noqa: F401\n")
endforeach ()
string(APPEND RIEMANN_PYTHON_IMPORTS "\n")
foreach (_riemann_import IN LISTS _riemann_own_imports)
  string(APPEND RIEMANN_PYTHON_IMPORTS "from .${_riemann_import} import *  # noqa: F401,F403\n")
endforeach ()
string(REPLACE ";" ", " RIEMANN_PYTHON_MODULE_NAMES "${_riemann_own_imports}")

configure_file(
  "${CMAKE_CURRENT_LIST_DIR}/riemann__init__.py.in"
  "${RIEMANN_PYTHONPATH}/riemann/__init__.py"
  @ONLY)
install(
  FILES       "${RIEMANN_PYTHONPATH}/riemann/__init__.py"
  DESTINATION "${RIEMANN_PYTHON_DESTINATION}/riemann"
  COMPONENT   python)
