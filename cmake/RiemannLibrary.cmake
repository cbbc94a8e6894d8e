# riemann_add_library(<Name>
#   CLASSES         <Class>...       # <Class>.h + <Class>.cxx, headers installed
#   HEADERS         <file.h>...      # more installed headers (header-only parts)
#   PRIVATE_SOURCES <file.cxx>...    # compiled, nothing installed
#   PRIVATE_HEADERS <file.h>...)     # not installed (they expose internals)
#
# A VTK-free library of the toolkit (Common/Metric, Rendering/Core,
# Rendering/ImageIO): target Riemann<Name>, alias Riemann::<Name>, export
# macro RIEMANN<NAME>_EXPORT in the generated Riemann<Name>Export.h (symbols
# are hidden by default), installed in the RiemannVTK export set with the VTK
# modules (they link to it publicly). The VTK-free check (CheckNoVTK) runs on
# every folder that calls this.
include(GenerateExportHeader)

set_property(GLOBAL PROPERTY RIEMANN_VTK_FREE_FOLDERS "")
set_property(GLOBAL PROPERTY RIEMANN_PLAIN_LIBRARIES "")

function (riemann_add_library name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" ""
    "CLASSES;HEADERS;PRIVATE_SOURCES;PRIVATE_HEADERS")
  set(target "Riemann${name}")
  string(TOUPPER "${target}" upper)
  set(sources ${arg_PRIVATE_SOURCES})
  set(headers ${arg_HEADERS})
  foreach (class IN LISTS arg_CLASSES)
    list(APPEND sources "${class}.cxx")
    list(APPEND headers "${class}.h")
  endforeach ()

  add_library(${target} ${sources} ${headers} ${arg_PRIVATE_HEADERS})
  add_library(Riemann::${name} ALIAS ${target})
  generate_export_header(${target}
    BASE_NAME         ${target}
    EXPORT_MACRO_NAME ${upper}_EXPORT
    EXPORT_FILE_NAME  "${CMAKE_CURRENT_BINARY_DIR}/${target}Export.h")
  target_include_directories(${target}
    PUBLIC
      "$<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}>"
      "$<BUILD_INTERFACE:${CMAKE_CURRENT_BINARY_DIR}>"
      "$<INSTALL_INTERFACE:${RIEMANN_HEADERS_DESTINATION}>")
  set_target_properties(${target} PROPERTIES
    # Exported (and found by consumers) as Riemann::<Name>, like the VTK
    # modules in the same export set.
    EXPORT_NAME ${name}
    VERSION     "${PROJECT_VERSION}"
    SOVERSION   "${RIEMANN_SOVERSION}")

  install(TARGETS ${target}
    EXPORT   RiemannVTK
    RUNTIME  DESTINATION "${CMAKE_INSTALL_BINDIR}"    COMPONENT runtime
    LIBRARY  DESTINATION "${CMAKE_INSTALL_LIBDIR}"    COMPONENT runtime
             NAMELINK_COMPONENT development
    ARCHIVE  DESTINATION "${CMAKE_INSTALL_LIBDIR}"    COMPONENT development)
  install(
    FILES ${headers} "${CMAKE_CURRENT_BINARY_DIR}/${target}Export.h"
    DESTINATION "${RIEMANN_HEADERS_DESTINATION}"
    COMPONENT   development)
  set_property(GLOBAL APPEND PROPERTY RIEMANN_VTK_FREE_FOLDERS "${CMAKE_CURRENT_SOURCE_DIR}")
  set_property(GLOBAL APPEND PROPERTY RIEMANN_PLAIN_LIBRARIES "${target}")
endfunction ()
