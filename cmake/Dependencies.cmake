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

if(REVOLVE_BUILD_DEMOS OR REVOLVE_BUILD_TESTS OR REVOLVE_BUILD_BENCH OR REVOLVE_FUZZ)
  find_package(CLI11 REQUIRED)
  find_package(TBB REQUIRED)
endif()

if(REVOLVE_BUILD_DEMOS)
  find_package(nlohmann_json 3 REQUIRED)   # the scene format (demo/io)
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
