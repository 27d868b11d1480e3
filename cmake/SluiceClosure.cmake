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

# sluice_add_closure_test(<target> [NAME test_name] [TIME_LIMIT seconds])
#
# Registers the conformance battery on a closure library as a ctest:
# `sluice check-closure $<TARGET_FILE:target>` (ABI and schema, bounds, every
# output written, batch invariance, derivatives, inputs outside validity,
# reference values, concurrency), passing when every check passes. The test
# is named <target>_check_closure unless NAME is given. The sluice command is
# SLUICE_EXECUTABLE (set by find_package(sluice)) or, inside the sluice
# project, its `sluice` target. Call enable_testing() first.
function(sluice_add_closure_test target)
  cmake_parse_arguments(ARG "" "NAME;TIME_LIMIT" "" ${ARGN})
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "sluice_add_closure_test(${target}): unexpected arguments ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT TARGET ${target})
    message(FATAL_ERROR "sluice_add_closure_test(${target}): no such target (build it with sluice_add_closure first)")
  endif()
  if(NOT ARG_NAME)
    set(ARG_NAME ${target}_check_closure)
  endif()
  if(SLUICE_EXECUTABLE)
    set(_sluice "${SLUICE_EXECUTABLE}")
  elseif(TARGET sluice)
    set(_sluice "$<TARGET_FILE:sluice>")
  else()
    message(FATAL_ERROR "sluice_add_closure_test(${target}): no sluice command (find_package(sluice) sets SLUICE_EXECUTABLE)")
  endif()
  set(_limit "")
  if(ARG_TIME_LIMIT)
    set(_limit --time-limit ${ARG_TIME_LIMIT})
  endif()
  add_test(NAME ${ARG_NAME} COMMAND "${_sluice}" check-closure "$<TARGET_FILE:${target}>" ${_limit})
  # only the library named is loaded; the search path plays no part
  set_tests_properties(${ARG_NAME} PROPERTIES ENVIRONMENT "SLUICE_PLUGIN_PATH=" LABELS "closure")
endfunction()
