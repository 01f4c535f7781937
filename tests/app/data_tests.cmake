# The tests whose scripts include require_data.cmake (given -DDATA=...): skipped by the line it prints when
# the mocap data is missing. Included by tests/app and tests/viewer.
set(MOBB_DATA_SKIP "skipped: mocap data not found in ")
function(mobb_data_tests)
  set_tests_properties(${ARGN} PROPERTIES SKIP_REGULAR_EXPRESSION "${MOBB_DATA_SKIP}")
endfunction()
