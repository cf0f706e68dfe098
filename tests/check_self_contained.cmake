# Fails when a tracked file points outside the repository: at the sibling directory the project was
# developed beside (a "../" path to it) or at its copy of the seed notes. The notes are cited as
# seeds 000, 001 and 002, with full entries in docs/references.md.
# Run by ctest as `self_contained`:  cmake -DSOURCE_DIR=<repository> -P check_self_contained.cmake
#
# Excluded for now: lib/include/, whose headers are being rewritten to cite "seed 002
# (docs/references.md)"; remove it from `excluded` once they are.
cmake_minimum_required(VERSION 3.25)
set(excluded lib/include/)

# The patterns are assembled so that this file does not match them itself.
set(name "shared")
set(patterns "../${name}" "${name}/seeds")

find_package(Git QUIET)
set(files)
if(GIT_FOUND AND EXISTS ${SOURCE_DIR}/.git)
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} ls-files
                  OUTPUT_VARIABLE listing RESULT_VARIABLE rc OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(rc)
    message(FATAL_ERROR "git ls-files failed in ${SOURCE_DIR}: ${rc}")
  endif()
  string(REPLACE "\n" ";" files "${listing}")
else()
  # Not a git checkout (an exported tree): every file but build trees and generated reports' plots.
  file(GLOB_RECURSE files RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/*)
  list(FILTER files EXCLUDE REGEX "^(build[^/]*|\\.git)/")
endif()
list(FILTER files EXCLUDE REGEX "\\.(png|jpg|gz|zip)$")
set(kept)
foreach(f IN LISTS files)
  set(keep TRUE)
  foreach(prefix IN LISTS excluded)
    string(FIND "${f}" "${prefix}" at)
    if(at EQUAL 0)
      set(keep FALSE)
    endif()
  endforeach()
  if(keep)
    list(APPEND kept ${f})
  endif()
endforeach()
set(files ${kept})

set(hits)
list(LENGTH files count)
foreach(f IN LISTS files)
  if(IS_DIRECTORY ${SOURCE_DIR}/${f} OR NOT EXISTS ${SOURCE_DIR}/${f})
    continue()
  endif()
  file(READ ${SOURCE_DIR}/${f} content)
  foreach(p IN LISTS patterns)
    string(FIND "${content}" "${p}" at)
    if(NOT at EQUAL -1)
      # The line of the first occurrence: one plus the newlines before it.
      string(SUBSTRING "${content}" 0 ${at} before)
      string(REGEX MATCHALL "\n" newlines "${before}")
      list(LENGTH newlines line)
      math(EXPR line "${line} + 1")
      list(APPEND hits "${f}:${line}: mentions \"${p}\"")
    endif()
  endforeach()
endforeach()
if(hits)
  list(JOIN hits "\n  " text)
  message(FATAL_ERROR "files point outside the repository:\n  ${text}")
endif()
message(STATUS "${count} tracked files checked (excluded: ${excluded})")
