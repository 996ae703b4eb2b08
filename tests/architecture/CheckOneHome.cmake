# Fails when one of the physics value types (SYSTOLE_PHYSICS_TYPES in cmake/Architecture.cmake:
# Waveform, Harmonic, Drive, PathKey, InteractionKind, Floor) is declared in more than one
# file under SOURCE_DIR, or anywhere but its home folder (physics/): a second declaration is
# a copy that drifts apart and needs a field-by-field translation. A declaration is a
# definition (`struct Drive {`, `enum class Waveform : int {`), a forward declaration or an
# alias (`using Drive = ...`, `typedef ... Drive;`); a using-declaration
# (`using physics::Drive;`) names the one type and is not counted.
# Run as: cmake -DSOURCE_DIR=<dir with module folders> -P CheckOneHome.cmake
# (ctest: architecture.one_home; architecture.one_home_catches_a_copy proves it can fail).
cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/../../cmake/Architecture.cmake)
if(NOT SOURCE_DIR)
  message(FATAL_ERROR "usage: cmake -DSOURCE_DIR=<src> -P CheckOneHome.cmake")
endif()

set(violations "")
file(GLOB_RECURSE files RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/*.h ${SOURCE_DIR}/*.cpp)
list(SORT files)
foreach(name IN LISTS SYSTOLE_PHYSICS_TYPES)
  # The name as a whole word after a class key, or as an alias's or a typedef's new name.
  set(keyed "^[ \t]*(template[ \t]*<[^>]*>[ \t]*)?(struct|class|union|enum|enum[ \t]+class|enum[ \t]+struct)[ \t]+${name}([ \t]*[:{;]|[ \t]+final|[ \t]*$)")
  set(alias "^[ \t]*using[ \t]+${name}[ \t]*=|^[ \t]*typedef[ \t].*[^A-Za-z0-9_]${name}[ \t]*;")
  set(homes "")
  foreach(file IN LISTS files)
    file(STRINGS ${SOURCE_DIR}/${file} lines REGEX "${keyed}|${alias}")
    if(lines)
      list(APPEND homes ${file})
    endif()
  endforeach()
  list(LENGTH homes count)
  if(count GREATER 1)
    string(REPLACE ";" ", " where "${homes}")
    string(APPEND violations "  ${name} is declared in ${count} files: ${where}; declare it once, in ${SYSTOLE_PHYSICS_HOME}/, and use it elsewhere with `using ${SYSTOLE_PHYSICS_HOME}::${name};`\n")
  endif()
  foreach(file IN LISTS homes)
    if(NOT file MATCHES "^${SYSTOLE_PHYSICS_HOME}/")
      string(APPEND violations "  ${name} is declared in ${file}, outside its home ${SYSTOLE_PHYSICS_HOME}/\n")
    endif()
  endforeach()
endforeach()

if(violations)
  message(FATAL_ERROR "Physics value types with more than one home (docs/architecture.md, cmake/Architecture.cmake):\n${violations}")
endif()
list(LENGTH files count)
message(STATUS "architecture: ${count} files, each physics value type declared once, in ${SYSTOLE_PHYSICS_HOME}/")
