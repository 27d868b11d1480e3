# FindSuiteSparse: Debian 12's libsuitesparse-dev (5.12) ships no CMake config
# and no pkg-config file, so look for the headers and libraries directly.
#
# Defines SuiteSparse_FOUND, SuiteSparse_INCLUDE_DIR and the imported targets
# SuiteSparse::umfpack, SuiteSparse::klu, SuiteSparse::cholmod and
# SuiteSparse::SuiteSparse (all three with their ordering libraries).
find_path(SuiteSparse_INCLUDE_DIR umfpack.h PATH_SUFFIXES suitesparse)

set(_ss_libs umfpack klu cholmod amd colamd camd ccolamd btf suitesparseconfig)
set(_ss_vars SuiteSparse_INCLUDE_DIR)
foreach(_lib IN LISTS _ss_libs)
  find_library(SuiteSparse_${_lib}_LIBRARY NAMES ${_lib})
  list(APPEND _ss_vars SuiteSparse_${_lib}_LIBRARY)
endforeach()

if(SuiteSparse_INCLUDE_DIR AND EXISTS "${SuiteSparse_INCLUDE_DIR}/SuiteSparse_config.h")
  file(STRINGS "${SuiteSparse_INCLUDE_DIR}/SuiteSparse_config.h" _ss_ver
       REGEX "#define SUITESPARSE_(MAIN|SUB)_VERSION[ \t]+[0-9]+")
  string(REGEX REPLACE ".*MAIN_VERSION[ \t]+([0-9]+).*" "\\1" _ss_major "${_ss_ver}")
  string(REGEX REPLACE ".*SUB_VERSION[ \t]+([0-9]+).*" "\\1" _ss_minor "${_ss_ver}")
  set(SuiteSparse_VERSION "${_ss_major}.${_ss_minor}")
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(SuiteSparse REQUIRED_VARS ${_ss_vars} VERSION_VAR SuiteSparse_VERSION)

if(SuiteSparse_FOUND)
  foreach(_lib IN LISTS _ss_libs)
    if(NOT TARGET SuiteSparse::${_lib})
      add_library(SuiteSparse::${_lib} UNKNOWN IMPORTED)
      set_target_properties(SuiteSparse::${_lib} PROPERTIES
        IMPORTED_LOCATION "${SuiteSparse_${_lib}_LIBRARY}"
        INTERFACE_INCLUDE_DIRECTORIES "${SuiteSparse_INCLUDE_DIR}")
    endif()
  endforeach()
  set_property(TARGET SuiteSparse::umfpack APPEND PROPERTY INTERFACE_LINK_LIBRARIES
               SuiteSparse::cholmod SuiteSparse::amd SuiteSparse::suitesparseconfig)
  set_property(TARGET SuiteSparse::klu APPEND PROPERTY INTERFACE_LINK_LIBRARIES
               SuiteSparse::btf SuiteSparse::amd SuiteSparse::colamd SuiteSparse::suitesparseconfig)
  set_property(TARGET SuiteSparse::cholmod APPEND PROPERTY INTERFACE_LINK_LIBRARIES
               SuiteSparse::amd SuiteSparse::colamd SuiteSparse::camd SuiteSparse::ccolamd
               SuiteSparse::suitesparseconfig)
  if(NOT TARGET SuiteSparse::SuiteSparse)
    add_library(SuiteSparse::SuiteSparse INTERFACE IMPORTED)
    set_property(TARGET SuiteSparse::SuiteSparse PROPERTY INTERFACE_LINK_LIBRARIES
                 SuiteSparse::umfpack SuiteSparse::klu SuiteSparse::cholmod m)
  endif()
endif()
mark_as_advanced(${_ss_vars})
