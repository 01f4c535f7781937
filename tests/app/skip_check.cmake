# The mocap data skip itself, run where the data is (CI): every test of BUILD_DIR's tests/app and
# tests/viewer whose command passes -DDATA= (their scripts include require_data.cmake) is run by a ctest of
# its own with MOBB_DATA naming a folder that does not exist. MODE skip (MOBB_REQUIRE_DATA unset): ctest must
# report each one skipped and pass. MODE require (MOBB_REQUIRE_DATA=1): each one must fail.
# Inputs: BUILD_DIR, CTEST (the ctest executable), WORK (a folder of its own), MODE.
cmake_minimum_required(VERSION 3.19)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
# A test project of its own (its Testing/ log apart from the build's) holding the build's tests.
set(testfile "")
foreach(dir tests/app tests/viewer)
  if(EXISTS ${BUILD_DIR}/${dir}/CTestTestfile.cmake)
    string(APPEND testfile "include(\"${BUILD_DIR}/${dir}/CTestTestfile.cmake\")\n")
  endif()
endforeach()
file(WRITE ${WORK}/CTestTestfile.cmake "${testfile}")

# The tests given -DDATA=, from the listing's "N: Test command: ..." and "  Test #N: NAME" lines.
execute_process(COMMAND ${CTEST} --test-dir ${WORK} -N -V OUTPUT_VARIABLE listing RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "ctest -N failed:\n${listing}")
endif()
string(REGEX MATCHALL "\n[0-9]+: Test command: [^\n]*\"-DDATA=[^\n]*" commands "${listing}")
set(names "")
foreach(command IN LISTS commands)
  string(REGEX MATCH "^\n([0-9]+):" _ "${command}")
  string(REGEX MATCH "\n  Test +#${CMAKE_MATCH_1}: ([A-Za-z0-9_.-]+)" _ "${listing}")
  list(APPEND names ${CMAKE_MATCH_1})
endforeach()
list(LENGTH names count)
if(count EQUAL 0)
  message(FATAL_ERROR "no test passes -DDATA= in ${BUILD_DIR}/tests/{app,viewer}")
endif()
string(REPLACE ";" "|" regex "${names}")

# -FA: no fixture setups added (they would run for real).
if(MODE STREQUAL "skip")
  set(env --unset=MOBB_REQUIRE_DATA)
  set(want Skipped)
else()
  set(env MOBB_REQUIRE_DATA=1)
  set(want Failed)
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env MOBB_DATA=${WORK}/no_such_folder ${env}
                        ${CTEST} --test-dir ${WORK} -R "^(${regex})$" -FA ".*"
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE code)
message("${out}${err}")
foreach(name IN LISTS names)
  if(NOT out MATCHES "\n[ \t]+[0-9]+ - ${name} \\(${want}\\)")
    message(FATAL_ERROR "${name} was not reported ${want} without the mocap data (MODE ${MODE})")
  endif()
endforeach()
if(MODE STREQUAL "skip" AND NOT code EQUAL 0)
  message(FATAL_ERROR "ctest failed although every test was to be skipped")
elseif(MODE STREQUAL "require" AND code EQUAL 0)
  message(FATAL_ERROR "ctest passed although MOBB_REQUIRE_DATA=1 and no data")
endif()
message("${count} tests ${want} (MODE ${MODE}): ${names}")
