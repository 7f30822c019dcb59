# SPDX-License-Identifier: MIT
# One helper adds a GoogleTest file and registers its tests with CTest.
include(GoogleTest)

# A sanitized build (FLANGE_SANITIZE) runs the tests several times slower: their time limits are
# this many times longer there (flange_scaled_timeout).
if(FLANGE_SANITIZE)
  set(FLANGE_TIMEOUT_SCALE 5)
else()
  set(FLANGE_TIMEOUT_SCALE 1)
endif()

# flange_scaled_timeout(<out-var> <seconds>): a test's time limit in this build.
function(flange_scaled_timeout out seconds)
  math(EXPR scaled "${seconds} * ${FLANGE_TIMEOUT_SCALE}")
  set(${out} ${scaled} PARENT_SCOPE)
endfunction()

# flange_add_gtest(<unit>_test SOURCES <files> LIBS <targets> [TIMEOUT s] [TEST_PREFIX p] [STORE])
# TEST_PREFIX (e.g. "VehicleSos.") tells apart the same tests built for several coefficient sets.
# STORE: the tests run on both store backends (tests/host/store/store_test_backends.h), their
# PostgreSQL server the StorePostgres fixture's (tests/host/CMakeLists.txt).
function(flange_add_gtest name)
  cmake_parse_arguments(ARG "STORE" "TIMEOUT;TEST_PREFIX" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} flange_warnings GTest::gtest_main)
  # tests/: helpers shared by the test folders (test_files.h).
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
  target_compile_definitions(${name} PRIVATE
    FLANGE_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    FLANGE_BINARY_DIR="${PROJECT_BINARY_DIR}")
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 300)
  endif()
  flange_scaled_timeout(ARG_TIMEOUT ${ARG_TIMEOUT})
  set(store_properties "")
  if(ARG_STORE)
    find_package(PostgreSQL REQUIRED)
    find_package(SQLite3 REQUIRED)
    target_sources(${name} PRIVATE ${PROJECT_SOURCE_DIR}/tests/host/store/store_test_backends.cpp)
    target_link_libraries(${name} PRIVATE PostgreSQL::PostgreSQL SQLite::SQLite3)
    target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/tests/host/store)
    set(store_properties FIXTURES_REQUIRED StorePostgres ENVIRONMENT
        FLANGE_TEST_POSTGRES_STATE=${PROJECT_BINARY_DIR}/test_files/store_postgres_server)
  endif()
  gtest_discover_tests(${name} WORKING_DIRECTORY ${PROJECT_BINARY_DIR}
                       TEST_PREFIX "${ARG_TEST_PREFIX}"
                       PROPERTIES TIMEOUT ${ARG_TIMEOUT} ${store_properties} DISCOVERY_TIMEOUT 60)
endfunction()

# flange_camel_case(<out-var> <snake_name>): measurement_sos -> MeasurementSos, the prefix of the
# tests built per coefficient set.
function(flange_camel_case out name)
  string(REPLACE "_" ";" words "${name}")
  set(camel "")
  foreach(word IN LISTS words)
    string(SUBSTRING "${word}" 0 1 first)
    string(SUBSTRING "${word}" 1 -1 rest)
    string(TOUPPER "${first}" first)
    string(APPEND camel "${first}${rest}")
  endforeach()
  set(${out} "${camel}" PARENT_SCOPE)
endfunction()
