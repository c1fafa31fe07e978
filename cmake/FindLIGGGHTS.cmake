# Finds Debian's LIGGGHTS 3.8 shared library (package libliggghts-dev).
# Debian ships no pkg-config or CMake file for it, hence this module.
# Defines the imported target LIGGGHTS::LIGGGHTS (headers + libliggghts + MPI).
find_path(LIGGGHTS_INCLUDE_DIR NAMES lammps.h library.h
          PATHS /usr/include/liggghts PATH_SUFFIXES liggghts)
find_library(LIGGGHTS_LIBRARY NAMES liggghts)
find_program(LIGGGHTS_EXECUTABLE NAMES liggghts)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(LIGGGHTS
  REQUIRED_VARS LIGGGHTS_LIBRARY LIGGGHTS_INCLUDE_DIR)

if(LIGGGHTS_FOUND AND NOT TARGET LIGGGHTS::LIGGGHTS)
  if(NOT TARGET MPI::MPI_CXX)
    find_package(MPI REQUIRED COMPONENTS CXX)
  endif()
  add_library(LIGGGHTS::LIGGGHTS SHARED IMPORTED)
  set_target_properties(LIGGGHTS::LIGGGHTS PROPERTIES
    IMPORTED_LOCATION "${LIGGGHTS_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${LIGGGHTS_INCLUDE_DIR}"
    # SYSTEM: LIGGGHTS's own headers are not -Wall -Wextra clean; our code must be.
    INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${LIGGGHTS_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES MPI::MPI_CXX)
endif()
mark_as_advanced(LIGGGHTS_INCLUDE_DIR LIGGGHTS_LIBRARY LIGGGHTS_EXECUTABLE)
