# Third-party packages, all from Debian 12 (scripts/install-deps.sh installs them).
# The library itself needs only Embree; the rest serve the applications and tests.

find_package(embree 3 REQUIRED)   # imported target `embree` (not embree::embree)

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
