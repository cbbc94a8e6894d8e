# riemann_prepare_paraview_package(<out_dir> <hierarchy_dir>)
#
# Debian's paraview-dev, usable without python3-paraview: a copy of
# /usr/lib/x86_64-linux-gnu/cmake/paraview-5.11 in <out_dir>, mended for the
# two gaps in Debian's packaging (Documentation/ParaView.md, "How it is built"):
#
# - its package files name files that only python3-paraview installs (the
#   Python modules, pvpython); find_package(ParaView) stops at the first. The
#   existence check skips those (nothing here uses ParaView's Python);
# - the wrapping hierarchy files that client-server wrapping reads are in
#   python3-paraview too. They are taken from <hierarchy_dir>, python3-paraview's
#   .deb unpacked (not installed: it conflicts with python3-vtk9); run.sh
#   unpacks it.
#
# The copies keep pointing at /usr: each targets, prefix and VTK-m config file
# computes the install prefix by walking up from where it lies, which in the
# copy is the build tree (a walk that reaches "/" found /usr only through
# Debian's /lib -> /usr/lib link, and only for a build tree at that depth).
function (riemann_prepare_paraview_package out_dir hierarchy_dir)
  set(source_dir "/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11")
  # Every file (the templates, paraview_plugin.h.in, ...); the .cmake ones mended.
  file(GLOB_RECURSE files RELATIVE "${source_dir}" "${source_dir}/*")
  foreach (file IN LISTS files)
    set(from "${source_dir}/${file}")
    set(to "${out_dir}/${file}")
    # Mended once per change of the system's file or of this mending
    # (re-configures are cheap).
    if (EXISTS "${to}" AND NOT "${from}" IS_NEWER_THAN "${to}"
        AND NOT "${CMAKE_CURRENT_FUNCTION_LIST_FILE}" IS_NEWER_THAN "${to}")
      continue ()
    endif ()
    if (NOT file MATCHES "\\.cmake$")
      configure_file("${from}" "${to}" COPYONLY)
      continue ()
    endif ()
    file(READ "${from}" text)
    get_filename_component(from_dir "${from}" DIRECTORY)
    string(REPLACE [[set(_vtk_module_import_prefix "${CMAKE_CURRENT_LIST_DIR}")]]
      "set(_vtk_module_import_prefix \"${from_dir}\")" text "${text}")
    string(REPLACE [[get_filename_component(PACKAGE_PREFIX_DIR "${CMAKE_CURRENT_LIST_DIR}/]]
      "get_filename_component(PACKAGE_PREFIX_DIR \"${from_dir}/" text "${text}")
    string(REPLACE [[if(_IMPORT_PREFIX STREQUAL "/")]]
      "set(_IMPORT_PREFIX \"/usr\")\nif(_IMPORT_PREFIX STREQUAL \"/\")" text "${text}")
    string(REPLACE [[if(NOT EXISTS "${_cmake_file}")]]
      [[if(NOT EXISTS "${_cmake_file}" AND NOT _cmake_file MATCHES "dist-packages|pvpython")]]
      text "${text}")
    string(REPLACE [[${_vtk_module_import_prefix}/lib/x86_64-linux-gnu/vtk/hierarchy/ParaView]]
      "${hierarchy_dir}" text "${text}")
    file(WRITE "${to}" "${text}")
  endforeach ()
endfunction ()
