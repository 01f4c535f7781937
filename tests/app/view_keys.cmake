# Real key presses (xdotool) in a real window (xvfb-run) on SCENE: each of KEYS must change the
# window's screenshot from the one taken with no key pressed (png_check --differs-from).
# Skipped without the mocap data (require_data.cmake).
include(${CMAKE_CURRENT_LIST_DIR}/require_data.cmake)
file(MAKE_DIRECTORY ${OUTDIR})
function(shot name key)
  set(png ${OUTDIR}/view_key_${name}.png)
  file(REMOVE ${png})
  # A fresh settings folder per run: a camera kept from an earlier run would change the picture.
  set(ENV{XDG_CONFIG_HOME} ${OUTDIR}/config_key_${name})
  file(REMOVE_RECURSE $ENV{XDG_CONFIG_HOME})
  # -noreset: see x11_window.sh.
  execute_process(COMMAND ${XVFB_RUN} -a -s "-screen 0 1400x900x24 -noreset"
                          ${DRIVER} ${MOBB} ${SCENE} ${png} 100000 ${key}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0 OR NOT EXISTS ${png})
    message(FATAL_ERROR "mobb view with key '${key}' exited ${code}\nstdout: ${out}\nstderr: ${err}")
  endif()
endfunction()
shot(none "")
foreach(key IN LISTS KEYS)
  string(REPLACE "+" "_" name ${key})
  shot(${name} ${key})
  execute_process(COMMAND ${PNG_CHECK} ${OUTDIR}/view_key_${name}.png --differs-from ${OUTDIR}/view_key_none.png
                  RESULT_VARIABLE code OUTPUT_VARIABLE out)
  message("${key}: ${out}")
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "key ${key} did not change the window (see ${OUTDIR}/view_key_${name}.png)")
  endif()
endforeach()
