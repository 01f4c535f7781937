# Every external package comes from Debian (see scripts/install-deps); nothing is downloaded or copied.
find_package(glm CONFIG REQUIRED)              # libglm-dev
find_package(TinyGLTF CONFIG REQUIRED)         # libtinygltf-dev
find_package(assimp CONFIG REQUIRED)           # libassimp-dev (FBX, Collada, ...)
find_package(nlohmann_json CONFIG REQUIRED)    # nlohmann-json3-dev
find_package(CLI11 CONFIG REQUIRED)            # libcli11-dev
find_package(tinyxml2 CONFIG REQUIRED)         # libtinyxml2-dev (SteerSuite test cases)
find_package(PkgConfig REQUIRED)
pkg_check_modules(HDF5 REQUIRED IMPORTED_TARGET hdf5)  # libhdf5-dev: crowd records in HDF5 (its C API)
if(MOBB_BUILD_TESTS)
  find_package(GTest CONFIG REQUIRED)          # libgtest-dev
endif()
if(MOBB_BUILD_BENCH)
  find_package(benchmark CONFIG REQUIRED)      # libbenchmark-dev
endif()
if(MOBB_BUILD_VIEWER AND MOBB_BUILD_APP)
  include(third_party/viewer.cmake)            # GLFW, OSMesa, Dear ImGui, glad, stb
endif()
# The Python module (python/): Debian's interpreter by default (pyenv's may lack numpy), python3-dev,
# pybind11-dev, python3-numpy; pytest and matplotlib for its tests and example. Not in sanitizer or
# fuzzing builds (the interpreter would need the sanitizer runtime preloaded).
option(MOBB_BUILD_PYTHON "Build the Python module when pybind11 is found" ON)
if(MOBB_BUILD_PYTHON AND NOT MOBB_SANITIZE AND NOT MOBB_FUZZ)
  if(NOT Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter of the module and its tests")
  endif()
  find_package(Python3 COMPONENTS Interpreter Development.Module)
  if(Python3_FOUND)
    find_package(pybind11 CONFIG QUIET)
  endif()
  if(NOT pybind11_FOUND)
    message(STATUS "mobb: Python module not built (pybind11-dev or python3-dev not found)")
  endif()
endif()
