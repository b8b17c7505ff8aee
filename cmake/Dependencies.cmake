# Third-party packages, all from Debian 12 (scripts/install-deps.sh installs them).
# The library itself needs only Embree; the rest serve the applications and tests.

find_package(embree 3 REQUIRED)   # imported target `embree` (not embree::embree)

if(REVOLVE_BUILD_DEMOS OR REVOLVE_BUILD_TESTS OR REVOLVE_BUILD_BENCH OR REVOLVE_FUZZ)
  find_package(CLI11 REQUIRED)
  find_package(TBB REQUIRED)
endif()

if(REVOLVE_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()

if(REVOLVE_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
