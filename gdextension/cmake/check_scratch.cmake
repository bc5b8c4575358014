# Keeps the doctests from leaving anything in the system's temporary directory.
#
# CTest runs every doctest with TMPDIR=DIR (a folder of the build tree), so whatever a test
# forgets lands there, never in /tmp. This script is the fixture around them:
#   -DMODE=setup   -DDIR=...   empties DIR before the suite
#   -DMODE=check   -DDIR=...   fails, naming each entry, if the suite left anything in DIR
#   -DMODE=failing -DDIR=... -DTEST_BINARY=...   runs the hidden test case that fails on
#     purpose while holding scratch folders (test_scratch_dir.cpp) and checks that it did
#     fail and still removed them.
cmake_minimum_required(VERSION 3.22)

function(list_leftovers p_dir r_out)
  file(GLOB leftovers LIST_DIRECTORIES true RELATIVE "${p_dir}" "${p_dir}/*" "${p_dir}/.*")
  set(${r_out} "${leftovers}" PARENT_SCOPE)
endfunction()

if(NOT DIR)
  message(FATAL_ERROR "check_scratch.cmake: DIR not set")
endif()

if(MODE STREQUAL "setup")
  file(REMOVE_RECURSE "${DIR}")
  file(MAKE_DIRECTORY "${DIR}")
elseif(MODE STREQUAL "check")
  list_leftovers("${DIR}" leftovers)
  file(REMOVE_RECURSE "${DIR}")
  if(leftovers)
    message(FATAL_ERROR "the doctests left these in their temporary directory: ${leftovers}")
  endif()
  message(STATUS "the doctests left nothing in their temporary directory")
elseif(MODE STREQUAL "failing")
  file(REMOVE_RECURSE "${DIR}")
  file(MAKE_DIRECTORY "${DIR}")
  set(ENV{TMPDIR} "${DIR}")
  execute_process(
    COMMAND "${TEST_BINARY}" --no-skip "--test-case=scratch_dir: a failing test*"
    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  list_leftovers("${DIR}" leftovers)
  file(REMOVE_RECURSE "${DIR}")
  if(result EQUAL 0 OR NOT output MATCHES "test cases: *1 \\| *0 passed \\| *1 failed")
    message(FATAL_ERROR "the deliberately failing test case did not run and fail (exit ${result}):\n${output}")
  endif()
  if(leftovers)
    message(FATAL_ERROR "a failing test left these behind: ${leftovers}")
  endif()
  message(STATUS "the failing test case failed and removed its scratch folders")
else()
  message(FATAL_ERROR "check_scratch.cmake: MODE must be setup, check or failing")
endif()
