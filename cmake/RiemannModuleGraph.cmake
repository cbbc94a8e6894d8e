# riemann_write_module_graph(<file>)
#
# Writes the toolkit's module graph as CMake knows it, after every library
# is defined: for each Riemann library (plain, riemann_add_library; or VTK
# module, vtk.module), its folder, its kind, and its link dependencies as
# declared (target_link_libraries, vtk_module_link, vtk.module DEPENDS and
# PRIVATE_DEPENDS), public and private. This is the one declaration of the
# dependencies: the include check (Testing/CheckIncludes.py), the link check
# (Testing/CheckLinks.py) and the module table of Documentation/
# Architecture.md (Testing/CheckModuleTable.py) are all read against it
# (Testing/ModuleGraph.py). Entries are written as CMake holds them
# (generator expressions included); the Python side reads names out of them.
function (riemann_write_module_graph file)
  get_property(plain GLOBAL PROPERTY RIEMANN_PLAIN_LIBRARIES)
  set(names)
  foreach (target IN LISTS plain)
    get_target_property(export_name "${target}" EXPORT_NAME)
    list(APPEND names "Riemann::${export_name}")
  endforeach ()
  list(APPEND names ${ARGN})

  set(entries)
  foreach (name IN LISTS names)
    get_target_property(target "${name}" ALIASED_TARGET)
    get_target_property(folder "${target}" SOURCE_DIR)
    file(RELATIVE_PATH folder "${PROJECT_SOURCE_DIR}" "${folder}")
    if (target IN_LIST plain)
      set(kind "library")
    else ()
      set(kind "vtk-module")
    endif ()
    get_target_property(all "${target}" LINK_LIBRARIES)
    get_target_property(interface "${target}" INTERFACE_LINK_LIBRARIES)
    foreach (list_name IN ITEMS all interface)
      if (NOT ${list_name})
        set(${list_name})
      endif ()
      set(quoted)
      foreach (item IN LISTS ${list_name})
        string(REPLACE "\\" "\\\\" item "${item}")
        string(REPLACE "\"" "\\\"" item "${item}")
        list(APPEND quoted "\"${item}\"")
      endforeach ()
      list(JOIN quoted ", " ${list_name}_json)
    endforeach ()
    list(APPEND entries
      "  \"${name}\": {\"target\": \"${target}\", \"folder\": \"${folder}\", \"kind\": \"${kind}\",\n    \"link\": [${all_json}],\n    \"interface\": [${interface_json}]}")
  endforeach ()
  list(JOIN entries ",\n" body)
  file(WRITE "${file}.in-progress" "{\n${body}\n}\n")
  # Rewritten only when it changed, so that nothing depending on it rebuilds.
  file(COPY_FILE "${file}.in-progress" "${file}" ONLY_IF_DIFFERENT)
  file(REMOVE "${file}.in-progress")
endfunction ()
