# mobb view SCENE --frames 30 --screenshot OUT under xvfb-run, once the display answers (x11_run.sh);
# skipped without the mocap data (require_data.cmake).
include(${CMAKE_CURRENT_LIST_DIR}/require_data.cmake)
file(REMOVE ${OUT})
if(NOT DEFINED VIEW_ARGS)
  set(VIEW_ARGS ${SCENE})
endif()
# -noreset: see x11_window.sh.
execute_process(COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24 -noreset" ${CMAKE_CURRENT_LIST_DIR}/x11_run.sh
                        ${MOBB} view ${VIEW_ARGS} --frames 30 --screenshot ${OUT} --width 1024 --height 640
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("exit ${code}\nstdout: ${out}\nstderr: ${err}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "mobb view exited ${code}")
endif()
execute_process(COMMAND ${PNG_CHECK} ${OUT} RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "${OUT} looks blank")
endif()
