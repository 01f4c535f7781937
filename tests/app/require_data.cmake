# Included by the CLI test scripts that need the mocap data: with DATA set, stops unless DATA (or $MOBB_DATA)
# holds the CMU clips, as skipped when MOBB_REQUIRE_DATA is not 1 and as failed when it is. A skip prints
# MOBB_DATA_SKIP's line (tests/app/data_tests.cmake: the tests' SKIP_REGULAR_EXPRESSION) and then fails, as
# a script run by `cmake -P` cannot choose its exit code before CMake 3.29 (cmake_language(EXIT)).
if(DEFINED DATA)
  if(DEFINED ENV{MOBB_DATA})
    set(DATA $ENV{MOBB_DATA})
  endif()
  if(NOT EXISTS ${DATA}/cmu/007_01.bvh)
    if("$ENV{MOBB_REQUIRE_DATA}" STREQUAL "1")
      message(FATAL_ERROR "mocap data not found in ${DATA} and MOBB_REQUIRE_DATA=1")
    endif()
    message("skipped: mocap data not found in ${DATA}")
    message(FATAL_ERROR "no mocap data: set MOBB_DATA or run next to ../shared/mocap")
  endif()
endif()
