# Every external package comes from Debian (see scripts/install-deps); nothing is downloaded or copied.
find_package(glm CONFIG REQUIRED)              # libglm-dev
find_package(TinyGLTF CONFIG REQUIRED)         # libtinygltf-dev
find_package(assimp CONFIG REQUIRED)           # libassimp-dev (FBX, Collada, ...)
find_package(nlohmann_json CONFIG REQUIRED)    # nlohmann-json3-dev
find_package(CLI11 CONFIG REQUIRED)            # libcli11-dev
if(MOBB_BUILD_TESTS)
  find_package(GTest CONFIG REQUIRED)          # libgtest-dev
endif()
if(MOBB_BUILD_BENCH)
  find_package(benchmark CONFIG REQUIRED)      # libbenchmark-dev
endif()
if(MOBB_BUILD_VIEWER AND MOBB_BUILD_APP)
  include(third_party/viewer.cmake)            # GLFW, OSMesa, Dear ImGui, glad, stb
endif()
