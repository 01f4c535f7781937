# Exported crowds checked by the formats' own tools (issue 30): MODE validator runs Khronos' glTF-Validator
# (node + the npm package gltf-validator) on a .glb with bodies and a .gltf, and wants no error; MODE
# blender imports the .glb headless into Debian's Blender and checks one armature per agent and the
# animation's frame range. Each stops with "skipped: REASON" (ctest's SKIP_REGULAR_EXPRESSION) when its tool
# is not installed.
# Inputs: MOBB (the executable), RECORD (a crowd record), OUTDIR, SCRIPT_DIR, DATA.
include(${CMAKE_CURRENT_LIST_DIR}/require_data.cmake)
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  set(code ${code} PARENT_SCOPE)
  set(out "${out}" PARENT_SCOPE)
endfunction()
if(MODE STREQUAL "validator")
  find_program(NODE node)
  if(NOT NODE)
    message(FATAL_ERROR "skipped: node is not installed (apt-get install nodejs npm; npm install -g gltf-validator)")
  endif()
  execute_process(COMMAND npm root -g OUTPUT_VARIABLE root OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  set(ENV{NODE_PATH} "${root}")
  run(${MOBB} export-crowd ${RECORD} --out ${OUTDIR}/export_tools.glb --body --time 1:6)
  run(${MOBB} export-crowd ${RECORD} --out ${OUTDIR}/export_tools.gltf --joints major)
  foreach(f export_tools.glb export_tools.gltf)
    run(${NODE} ${SCRIPT_DIR}/gltf_validate.js ${OUTDIR}/${f})
    if(code EQUAL 77)
      message(FATAL_ERROR "skipped: the npm package gltf-validator is not installed")
    elseif(NOT code EQUAL 0)
      message(FATAL_ERROR "glTF-Validator reports errors in ${f}")
    endif()
  endforeach()
elseif(MODE STREQUAL "blender")
  find_program(BLENDER blender)
  if(NOT BLENDER)
    message(FATAL_ERROR "skipped: Blender is not installed (apt-get install blender; then ctest -R export_blender)")
  endif()
  run(${MOBB} export-crowd ${RECORD} --out ${OUTDIR}/export_blender.glb --body --time 0:4 --fps 30)
  # Debian's Blender 3.4 glTF importer still names numpy.bool, gone from the numpy Debian ships: the alias
  # is put back first (it only ever meant the builtin bool).
  run(${BLENDER} -b --factory-startup --python-expr
      "import numpy\nif not hasattr(numpy, 'bool'): numpy.bool = bool\nimport bpy\nbpy.ops.wm.read_factory_settings(use_empty=True)\nbpy.context.scene.render.fps = 30\nbpy.ops.import_scene.gltf(filepath='${OUTDIR}/export_blender.glb')\narm=[o for o in bpy.data.objects if o.type=='ARMATURE']\nacts=bpy.data.actions\nr=[a.frame_range for a in acts]\nprint('MOBB armatures %d frames %g %g' % (len(arm), min(x[0] for x in r), max(x[1] for x in r)))\n")
  string(REGEX MATCH "MOBB armatures ([0-9]+) frames ([0-9.]+) ([0-9.]+)" m "${out}")
  if(NOT m)
    message(FATAL_ERROR "Blender did not import the file")
  endif()
  if(NOT CMAKE_MATCH_1 EQUAL AGENTS)
    message(FATAL_ERROR "expected ${AGENTS} armatures, Blender made ${CMAKE_MATCH_1}")
  endif()
  # 0 .. 4 s with the scene at 30 fps: Blender frames 0 .. 120.
  if(NOT (CMAKE_MATCH_2 EQUAL 0 AND CMAKE_MATCH_3 EQUAL 120))
    message(FATAL_ERROR "the animation spans frames ${CMAKE_MATCH_2} .. ${CMAKE_MATCH_3}, expected 0 .. 120 (4 s at 30 fps)")
  endif()
endif()
