# The libraries a host links: every one is a target named agaa_<name>, reachable in-tree as the
# ALIAS agaa::<name> and from an installed prefix through find_package(agaa CONFIG) as the same
# agaa::<name> (EXPORT_NAME). Their headers resolve from the repository root in the build tree and
# from <prefix>/include/agaa once installed (the top-level CMakeLists.txt installs every target
# registered here, in the export set agaa-targets).
#
#   agaa_package(agaa_<name>)

set(AGAA_INSTALL_INCLUDEDIR include/agaa)

function(agaa_package target)
  if(NOT target MATCHES "^agaa_(.+)$")
    message(FATAL_ERROR "agaa_package(${target}): a packaged target is named agaa_<name>")
  endif()
  set(name ${CMAKE_MATCH_1})
  add_library(agaa::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  get_target_property(type ${target} TYPE)
  set(scope PUBLIC)
  if(type STREQUAL "INTERFACE_LIBRARY")
    set(scope INTERFACE)
  endif()
  target_include_directories(${target} ${scope} $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
                                                $<INSTALL_INTERFACE:${AGAA_INSTALL_INCLUDEDIR}>)
  set_property(GLOBAL APPEND PROPERTY AGAA_PACKAGE_TARGETS ${target})
endfunction()
