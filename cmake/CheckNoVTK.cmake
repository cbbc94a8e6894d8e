# cmake -DDIR=<folder> -P CheckNoVTK.cmake
#
# Fails when any file under DIR includes a VTK header. The folders of the
# VTK-free layer (riemann_add_library: Common/Metric, Rendering/Core,
# Rendering/ImageIO) are plain C++17: the VTK classes are thin adapters over
# them, and this check keeps them usable without VTK.
if (NOT DEFINED DIR OR NOT IS_DIRECTORY "${DIR}")
  message(FATAL_ERROR "CheckNoVTK: pass -DDIR=<folder> (got '${DIR}')")
endif ()

file(GLOB_RECURSE files LIST_DIRECTORIES false "${DIR}/*")
list(SORT files)
set(offenders)
foreach (file IN LISTS files)
  # Matches `#include <vtk...>` and `#include "vtk..."`, also `# include`.
  file(STRINGS "${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]vtk")
  foreach (line IN LISTS lines)
    file(RELATIVE_PATH rel "${DIR}" "${file}")
    string(STRIP "${line}" line)
    list(APPEND offenders "  ${rel}: ${line}")
  endforeach ()
endforeach ()

list(LENGTH files count)
if (offenders)
  string(REPLACE ";" "\n" offenders "${offenders}")
  message(FATAL_ERROR
    "VTK includes found in ${DIR} (it must stay VTK-free; put VTK code in "
    "a VTK module: Common/Core, Filters/*, Rendering/Scene, ...):\n${offenders}")
endif ()
message(STATUS "CheckNoVTK: ${count} files under ${DIR}, no VTK includes")
