# Collapsing a panel column in a real window (xvfb-run, xdotool): the default scene at 1280x720 shot with
# no key, then with KEY held (`[`: the left column collapses). Where the column stood the 3D view's
# background must show afterwards (column_check on RECT), and the settings file must keep the collapse.
# Skipped without the mocap data (require_data.cmake).
cmake_minimum_required(VERSION 3.19)
include(${REQUIRE_DATA})
file(MAKE_DIRECTORY ${OUTDIR})
function(shot name key)
  set(png ${OUTDIR}/view_column_${name}.png)
  file(REMOVE ${png})
  set(ENV{XDG_CONFIG_HOME} ${OUTDIR}/config_column_${name})  # fresh settings: the default layout
  file(REMOVE_RECURSE $ENV{XDG_CONFIG_HOME})
  # -noreset: see tests/app/x11_window.sh.
  execute_process(COMMAND ${XVFB_RUN} -a -s "-screen 0 1400x900x24 -noreset"
                          ${DRIVER} ${MOBB} ${SCENE} ${png} 100000 ${key}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0 OR NOT EXISTS ${png})
    message(FATAL_ERROR "mobb view with key '${key}' exited ${code}\nstdout: ${out}\nstderr: ${err}")
  endif()
endfunction()
shot(open "")
shot(collapsed ${KEY})
string(REPLACE "," ";" rect "${RECT}")
execute_process(COMMAND ${COLUMN_CHECK} ${OUTDIR}/view_column_open.png ${OUTDIR}/view_column_collapsed.png ${rect}
                RESULT_VARIABLE code OUTPUT_VARIABLE out)
message("${out}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the viewport did not take the column's place (see ${OUTDIR}/view_column_*.png)")
endif()
file(STRINGS ${OUTDIR}/config_column_collapsed/mobb/imgui.ini ini)
if(NOT "${INI_LINE}" IN_LIST ini)
  message(FATAL_ERROR "the settings file lacks '${INI_LINE}'")
endif()
