# tests/layers/no_python.cmake: stands in for the layer tests (layers,
# layers_selftest) when CMake found no Python 3 to run tests/layers/*.py.
# The test is skipped (its output matches the SKIP_REGULAR_EXPRESSION
# tests/CMakeLists.txt sets), except under CI (CI set and not "false"), where
# it fails: .ci/deps installs Python 3, so CI always checks the layers.
if(NOT "$ENV{CI}" STREQUAL "" AND NOT "$ENV{CI}" STREQUAL "false")
  message(FATAL_ERROR "FAIL: python3 not found (CI=$ENV{CI}); .ci/deps installs it, then reconfigure")
endif()
message("SKIP: python3 not found (apt-get install python3, then reconfigure)")
