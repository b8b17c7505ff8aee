# Third-party packages, all from Debian 12 or 13 (scripts/install-deps.sh installs them).
# revolve::core needs nothing; the Embree glue needs Embree 3.13 or 4.x; the rest serve the
# applications and tests.

# REVOLVE_EMBREE_VERSION chooses the Embree major version when a machine has both; by default,
# Embree 4 if found, else Embree 3.
set(REVOLVE_EMBREE_VERSION "auto" CACHE STRING "Embree major version to build against: auto, 3 or 4")
set_property(CACHE REVOLVE_EMBREE_VERSION PROPERTY STRINGS auto 3 4)
if(REVOLVE_EMBREE_VERSION STREQUAL "auto")
  find_package(embree 4 QUIET)
  if(NOT embree_FOUND)
    find_package(embree 3 QUIET)
  endif()
  if(NOT embree_FOUND)
    message(FATAL_ERROR "revolve needs Embree 3.13 or 4.x and found neither (Debian: libembree-dev; "
                        "elsewhere set embree_DIR to the folder holding embree-config.cmake)")
  endif()
elseif(REVOLVE_EMBREE_VERSION MATCHES "^[34]$")
  find_package(embree ${REVOLVE_EMBREE_VERSION} REQUIRED)
else()
  message(FATAL_ERROR "REVOLVE_EMBREE_VERSION is '${REVOLVE_EMBREE_VERSION}': it must be auto, 3 or 4")
endif()
# Imported target `embree` (not embree::embree) in both.
string(REGEX MATCH "^[0-9]+" REVOLVE_EMBREE_MAJOR "${embree_VERSION}")
set(REVOLVE_EMBREE_VERSION_FOUND "${embree_VERSION}")
if(REVOLVE_EMBREE_MAJOR STREQUAL "3" AND embree_VERSION VERSION_LESS 3.13)
  message(FATAL_ERROR "revolve needs Embree 3.13 or later of the 3 series; found ${embree_VERSION} (${embree_DIR})")
endif()
message(STATUS "revolve: Embree ${embree_VERSION} (${embree_DIR})")

if(REVOLVE_BUILD_TOOLS OR REVOLVE_BUILD_TESTS OR REVOLVE_BUILD_BENCH OR REVOLVE_FUZZ)
  find_package(CLI11 REQUIRED)
  find_package(TBB REQUIRED)
endif()

if(REVOLVE_BUILD_TOOLS)
  find_package(nlohmann_json 3 REQUIRED)   # the scene format (platform/io)
  find_package(OpenImageIO REQUIRED)       # revolve-render's images
  # Debian's OpenImageIO 2.4 target names /usr/include/opencv4 as an include directory, which
  # exists only with libopencv-dev; nothing here uses OpenCV, so drop the entry.
  foreach(property INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
    get_target_property(directories OpenImageIO::OpenImageIO ${property})
    if(directories)
      list(FILTER directories EXCLUDE REGEX "opencv4")
      set_target_properties(OpenImageIO::OpenImageIO PROPERTIES ${property} "${directories}")
    endif()
  endforeach()
endif()

if(REVOLVE_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()

if(REVOLVE_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()

# The Python package (python/, REVOLVE_BUILD_PYTHON): pybind11 and numpy for one interpreter. By
# default Debian's /usr/bin/python3, which sees Debian's python3-numpy and python3-pybind11: a
# python3 earlier on PATH (pyenv, a virtual environment without system packages) may not. Name
# another with -DPython3_EXECUTABLE=...; `pip install .` names its own.
set(REVOLVE_PYTHON_ENABLED OFF)
if(NOT REVOLVE_BUILD_PYTHON MATCHES "^(AUTO|ON|OFF)$")
  message(FATAL_ERROR "REVOLVE_BUILD_PYTHON is '${REVOLVE_BUILD_PYTHON}': it must be AUTO, ON or OFF")
endif()
if(REVOLVE_BUILD_PYTHON STREQUAL "ON" OR (REVOLVE_BUILD_PYTHON STREQUAL "AUTO" AND REVOLVE_BUILD_TOOLS AND NOT REVOLVE_SANITIZE
                                             AND NOT REVOLVE_FUZZ))
  set(missing "")
  if(NOT REVOLVE_BUILD_TOOLS)
    set(missing "the applications' libraries (REVOLVE_BUILD_TOOLS=ON)")
  else()
    if(NOT Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
      set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The Python interpreter the package is built for")
    endif()
    find_package(Python3 COMPONENTS Interpreter Development.Module QUIET)
    if(NOT Python3_FOUND)
      set(missing "Python 3 with its headers (Debian: python3-dev)")
    else()
      find_package(pybind11 2.10 CONFIG QUIET)
      execute_process(COMMAND ${Python3_EXECUTABLE} -c "import numpy" RESULT_VARIABLE numpy_status OUTPUT_QUIET ERROR_QUIET)
      if(NOT pybind11_FOUND)
        set(missing "pybind11 (Debian: python3-pybind11)")
      elseif(NOT numpy_status EQUAL 0)
        set(missing "numpy for ${Python3_EXECUTABLE} (Debian: python3-numpy)")
      endif()
    endif()
  endif()
  if(missing STREQUAL "")
    set(REVOLVE_PYTHON_ENABLED ON)
    execute_process(COMMAND ${Python3_EXECUTABLE} -c "import pytest" RESULT_VARIABLE pytest_status OUTPUT_QUIET ERROR_QUIET)
    if(pytest_status EQUAL 0)
      set(REVOLVE_PYTEST_FOUND ON)
    else()
      set(REVOLVE_PYTEST_FOUND OFF)
    endif()
    message(STATUS "revolve: Python package for ${Python3_EXECUTABLE} (Python ${Python3_VERSION}, pybind11 ${pybind11_VERSION})")
  elseif(REVOLVE_BUILD_PYTHON STREQUAL "ON")
    message(FATAL_ERROR "REVOLVE_BUILD_PYTHON=ON needs ${missing}")
  else()
    message(STATUS "revolve: Python package not built: it needs ${missing}")
  endif()
endif()

# The OSPRay module (ospray/, REVOLVE_BUILD_OSPRAY): OSPRay 3's package with its module SDK, and the
# ISPC compiler for the module's two ISPC entry points. Not in sanitizer or fuzzing builds unless
# asked for (OSPRay's own libraries are not instrumented).
set(REVOLVE_OSPRAY_ENABLED OFF)
if(NOT REVOLVE_BUILD_OSPRAY MATCHES "^(AUTO|ON|OFF)$")
  message(FATAL_ERROR "REVOLVE_BUILD_OSPRAY is '${REVOLVE_BUILD_OSPRAY}': it must be AUTO, ON or OFF")
endif()
if(REVOLVE_BUILD_OSPRAY STREQUAL "ON" OR (REVOLVE_BUILD_OSPRAY STREQUAL "AUTO" AND NOT REVOLVE_SANITIZE AND NOT REVOLVE_FUZZ))
  set(missing "")
  find_package(ospray 3 QUIET)
  if(NOT ospray_FOUND)
    set(missing "OSPRay 3 with its module SDK (Debian 13: libospray-dev; Debian 12 has none)")
  elseif(NOT REVOLVE_EMBREE_MAJOR EQUAL 4)
    set(missing "Embree 4 (OSPRay 3 traces with it; this build uses Embree ${embree_VERSION})")
  else()
    include(CheckLanguage)
    # check_language caches a compiler it did not find and never looks again: look again, so that
    # installing ispc after a first configure is enough.
    if(NOT CMAKE_ISPC_COMPILER)
      unset(CMAKE_ISPC_COMPILER CACHE)
    endif()
    check_language(ISPC)
    if(NOT CMAKE_ISPC_COMPILER)
      set(missing "the ISPC compiler (Debian 13: ispc)")
    endif()
  endif()
  if(missing STREQUAL "")
    set(REVOLVE_OSPRAY_ENABLED ON)
    message(STATUS "revolve: OSPRay module for OSPRay ${ospray_VERSION} (ISPC ${CMAKE_ISPC_COMPILER})")
  elseif(REVOLVE_BUILD_OSPRAY STREQUAL "ON")
    message(FATAL_ERROR "REVOLVE_BUILD_OSPRAY=ON needs ${missing}")
  else()
    set(REVOLVE_OSPRAY_MISSING "${missing}")
    message(STATUS "revolve: OSPRay module not built: it needs ${missing}")
  endif()
endif()
