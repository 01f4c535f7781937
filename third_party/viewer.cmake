# Viewer packages, all from Debian: GLFW (libglfw3-dev), OSMesa (libosmesa6-dev), OpenGL (libgl-dev),
# Dear ImGui 1.86 (libimgui-dev), stb (libstb-dev), and glad (python3-glad) generating the GL loader
# at build time. Every GL call goes through glad, so one code path drives a GLX window and OSMesa.
enable_language(C)   # the generated loader is C
find_package(OpenGL REQUIRED)
find_package(glfw3 CONFIG REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(OSMESA REQUIRED IMPORTED_TARGET osmesa)
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)   # Requires: stb, so -lstb comes along
find_program(MOBB_GLAD glad REQUIRED)

# glad: OpenGL 3.3 core loader, generated into the build tree (nothing generated is committed).
set(MOBB_GLAD_DIR ${CMAKE_BINARY_DIR}/glad)
add_custom_command(
  OUTPUT ${MOBB_GLAD_DIR}/src/gl.c ${MOBB_GLAD_DIR}/include/glad/gl.h
  COMMAND ${MOBB_GLAD} --quiet --reproducible --api gl:core=3.3 --out-path ${MOBB_GLAD_DIR} c
  COMMENT "Generating the OpenGL 3.3 core loader with glad"
  VERBATIM)
add_library(mobb_glad STATIC ${MOBB_GLAD_DIR}/src/gl.c)
target_include_directories(mobb_glad SYSTEM PUBLIC ${MOBB_GLAD_DIR}/include)
set_target_properties(mobb_glad PROPERTIES POSITION_INDEPENDENT_CODE ON)

# ImGui's GLFW and OpenGL3 backends compiled against glad: Debian's libimgui.a carries copies built
# with ImGui's own libGL loader, which cannot reach an OSMesa context. Third-party code: no mobb_flags.
set(MOBB_IMGUI_BACKENDS /usr/share/doc/libimgui-dev/examples/backends)
add_library(mobb_imgui_backends STATIC
  ${MOBB_IMGUI_BACKENDS}/imgui_impl_opengl3.cpp
  ${MOBB_IMGUI_BACKENDS}/imgui_impl_glfw.cpp)
target_compile_definitions(mobb_imgui_backends PRIVATE IMGUI_IMPL_OPENGL_LOADER_CUSTOM GLFW_INCLUDE_NONE)
target_compile_options(mobb_imgui_backends PRIVATE -include glad/gl.h -w)
target_include_directories(mobb_imgui_backends SYSTEM PUBLIC /usr/include/imgui/backends)
target_link_libraries(mobb_imgui_backends PUBLIC mobb_glad PkgConfig::IMGUI glfw)
