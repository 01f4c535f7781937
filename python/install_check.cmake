# Installs the build tree into WORK_DIR/prefix and imports the module from the site directory there
# (MOBB_PYTHON_INSTALL_DIR under the prefix), as `cmake --install` users will.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed: ${err}")
endif()
set(site ${WORK_DIR}/prefix/${SITE_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${site} ${PYTHON} -c
                "import mobb, mobb_dask, os, sys; sys.exit(0 if os.path.dirname(mobb.__file__) == os.path.dirname(mobb_dask.__file__) == sys.argv[1] else 1)" ${site}
                WORKING_DIRECTORY ${WORK_DIR}  # not the build tree's python/, which holds a module too
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "import mobb from ${site} failed (${rc}): ${out}${err}")
endif()
message("imported mobb from ${site}")
