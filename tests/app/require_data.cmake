# Included by the CLI test scripts that need the mocap data: with DATA set, exits 77 (skipped) unless
# DATA (or $MOBB_DATA) holds the CMU clips, and fails instead when MOBB_REQUIRE_DATA=1.
if(DEFINED DATA)
  if(DEFINED ENV{MOBB_DATA})
    set(DATA $ENV{MOBB_DATA})
  endif()
  if(NOT EXISTS ${DATA}/cmu/007_01.bvh)
    if("$ENV{MOBB_REQUIRE_DATA}" STREQUAL "1")
      message(FATAL_ERROR "mocap data not found in ${DATA} and MOBB_REQUIRE_DATA=1")
    endif()
    message("skipped: mocap data not found in ${DATA}")
    cmake_language(EXIT 77)
  endif()
endif()
