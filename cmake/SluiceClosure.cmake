# sluice_add_closure(<target> <source>... [OUTPUT_DIRECTORY dir] [INSTALL_DESTINATION dir])
#
# Builds a closure library: a shared object that includes only
# <sluice/closure.h>, exports only sl_closure_entry_v1, has no undefined
# symbols and no link to the sluice core. Used for the built-in closures and,
# through find_package(sluice), for third-party ones.
function(sluice_add_closure target)
  cmake_parse_arguments(ARG "" "OUTPUT_DIRECTORY;INSTALL_DESTINATION" "" ${ARGN})
  add_library(${target} MODULE ${ARG_UNPARSED_ARGUMENTS})
  set_target_properties(${target} PROPERTIES
    PREFIX ""
    C_STANDARD 11
    C_STANDARD_REQUIRED ON
    C_VISIBILITY_PRESET hidden)
  if(ARG_OUTPUT_DIRECTORY)
    set_target_properties(${target} PROPERTIES LIBRARY_OUTPUT_DIRECTORY "${ARG_OUTPUT_DIRECTORY}")
  endif()
  if(TARGET sluice::closure_headers)
    target_link_libraries(${target} PRIVATE sluice::closure_headers)
  endif()
  # No undefined symbols except libc and libm: a closure needs nothing else.
  # (Not with sanitizers, whose runtime the host provides.)
  get_property(_opts DIRECTORY PROPERTY LINK_OPTIONS)
  if(NOT "${_opts}" MATCHES "sanitize" AND NOT "${CMAKE_C_FLAGS}" MATCHES "sanitize")
    target_link_options(${target} PRIVATE "LINKER:--no-undefined")
  endif()
  target_link_libraries(${target} PRIVATE m)
  if(ARG_INSTALL_DESTINATION)
    install(TARGETS ${target} LIBRARY DESTINATION "${ARG_INSTALL_DESTINATION}")
  endif()
endfunction()
