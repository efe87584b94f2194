# cmake -DENGINE=DIR -DCHECKED="a.cpp;b.cpp" -P CheckedSources.cmake
# Fails when a source or header of the engine other than the listed ones mentions
# PHASEBOX_EXPENSIVE_CHECKS: only those are compiled a second time, with the checks, for
# phasebox_physics_checked (physics/CMakeLists.txt), so a check written anywhere else would
# never run in the checked suites.
cmake_minimum_required(VERSION 3.25)
file(GLOB_RECURSE files RELATIVE ${ENGINE} ${ENGINE}/*.cpp ${ENGINE}/*.h)
set(strays "")
foreach(file IN LISTS files)
  if(file IN_LIST CHECKED)
    continue()
  endif()
  file(STRINGS ${ENGINE}/${file} hits REGEX "PHASEBOX_EXPENSIVE_CHECKS")
  if(hits)
    list(APPEND strays ${file})
  endif()
endforeach()
if(strays)
  message(FATAL_ERROR "PHASEBOX_EXPENSIVE_CHECKS is read outside PHASEBOX_CHECKED_SOURCES "
    "(physics/CMakeLists.txt): ${strays}")
endif()
foreach(file IN LISTS CHECKED)
  file(STRINGS ${ENGINE}/${file} hits REGEX "#if PHASEBOX_EXPENSIVE_CHECKS")
  if(NOT hits)
    message(FATAL_ERROR "${file} is in PHASEBOX_CHECKED_SOURCES but has no "
      "#if PHASEBOX_EXPENSIVE_CHECKS")
  endif()
endforeach()
list(LENGTH files count)
message(STATUS "${count} engine files: the checks only in ${CHECKED}")
