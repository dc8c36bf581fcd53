# Helpers that give every target of ours the same language level, warnings and sanitizers.
# Third-party and generated code never goes through these, so it keeps its own flags.

set(EPOSP_WARNINGS -Wall -Wextra -Wpedantic -Werror -Wshadow -Wnon-virtual-dtor -Wconversion
    -Wno-sign-conversion)
set(EPOSP_SANITIZERS -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
if(EPOSP_BUILD_FUZZERS)
    if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
        message(FATAL_ERROR "EPOSP_BUILD_FUZZERS needs clang: -DCMAKE_CXX_COMPILER=clang++")
    endif()
    # libFuzzer steers by the coverage of our code, so all of it is instrumented for it; the
    # fuzzer's own main is linked into the fuzz binaries only (tests/fuzz).
    set(EPOSP_SANITIZE ON)
    list(APPEND EPOSP_SANITIZERS -fsanitize=fuzzer-no-link)
endif()

function(eposp_apply_defaults target scope)
    target_compile_features(${target} ${scope} cxx_std_20)
    if(NOT scope STREQUAL "INTERFACE")
        target_compile_options(${target} PRIVATE ${EPOSP_WARNINGS})
    endif()
    if(EPOSP_SANITIZE)
        if(NOT scope STREQUAL "INTERFACE")
            target_compile_options(${target} PRIVATE ${EPOSP_SANITIZERS})
        endif()
        target_link_options(${target} ${scope} ${EPOSP_SANITIZERS})
    endif()
endfunction()

# eposp_add_library(<folder> [SOURCES ...] [DEPENDS ...]) defines eposp::<folder> with its public
# headers in <folder>/include. A folder without sources yet is an INTERFACE library.
function(eposp_add_library name)
    cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
    set(target eposp_${name})
    if(ARG_SOURCES)
        add_library(${target} STATIC ${ARG_SOURCES})
        set(scope PUBLIC)
    else()
        add_library(${target} INTERFACE)
        set(scope INTERFACE)
    endif()
    add_library(eposp::${name} ALIAS ${target})
    target_include_directories(${target} ${scope} ${CMAKE_CURRENT_SOURCE_DIR}/include)
    target_link_libraries(${target} ${scope} ${ARG_DEPENDS})
    eposp_apply_defaults(${target} ${scope})
endfunction()

# eposp_add_executable(<name> SOURCES ... [DEPENDS ...])
function(eposp_add_executable name)
    cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
    add_executable(${name} ${ARG_SOURCES})
    target_link_libraries(${name} PRIVATE ${ARG_DEPENDS})
    eposp_apply_defaults(${name} PRIVATE)
endfunction()

# The sanitizer build compiles every file again with both sanitizers, and the test files are
# more than half of it. In them, AddressSanitizer stays: a test's stack objects that the code
# under test holds get their redzones and scope checks. UndefinedBehaviorSanitizer and line
# tables go: it checks the code under test, which keeps it, and not the tests' own arithmetic;
# a report still names the test's function. GoogleTest and the standard headers every test
# file parses are precompiled once per suite (docs/testing.md, Sanitizer build).
function(eposp_lighten_sanitized_tests target)
    target_compile_options(${target} PRIVATE -fno-sanitize=undefined -g0)
    target_precompile_headers(${target} PRIVATE <gtest/gtest.h> <gmock/gmock.h> <algorithm>
        <chrono> <cmath> <fstream> <optional> <sstream> <stdexcept> <string> <vector>)
endfunction()

# eposp_add_test_suite(<folder> SOURCES ... [DEPENDS ...]): one GoogleTest binary per top-level
# folder, each test registered with CTest and labelled with the folder (ctest -L <folder>).
function(eposp_add_test_suite folder)
    cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
    set(target eposp_${folder}_tests)
    eposp_add_executable(${target} SOURCES ${ARG_SOURCES}
        DEPENDS ${ARG_DEPENDS} eposp::test_directory GTest::gtest_main GTest::gmock)
    target_compile_definitions(${target} PRIVATE
        EPOSP_SOURCE_DIR="${PROJECT_SOURCE_DIR}" EPOSP_BINARY_DIR="${PROJECT_BINARY_DIR}")
    if(NOT EPOSP_BUILD_FUZZERS)
        # Test files are compiled unoptimised in every build: GCC takes about twice as long to
        # compile one at -O2 (or with UBSan at -O1) as at -O0, they are most of the build, and
        # the code under test keeps its own optimisation, so the suites run as fast.
        target_compile_options(${target} PRIVATE -O0)
    endif()
    if(EPOSP_SANITIZE AND NOT EPOSP_BUILD_FUZZERS)
        eposp_lighten_sanitized_tests(${target})
    endif()
    eposp_register_gtest(${target} ${folder})
endfunction()

# Under the sanitizers, starting an instrumented test process and its leak check at exit cost
# more than most tests themselves (one process per test made the sanitizer suite ten times
# slower than the same tests in a few processes), so a binary runs in this many shards there.
set(EPOSP_SANITIZER_SHARDS 8)

# eposp_register_gtest(<target> <label> [NAME <name>] [ENVIRONMENT <VAR=value>...]): registers a
# GoogleTest binary with CTest. Each test is its own CTest test (`ctest -R Suite.Name` runs one),
# or, with NAME, the whole binary is one test of that name; under the sanitizers either becomes
# <name or target>.shard<i> for i below EPOSP_SANITIZER_SHARDS (GoogleTest's own sharding).
function(eposp_register_gtest target label)
    cmake_parse_arguments(ARG "" "NAME" "ENVIRONMENT" ${ARGN})
    if(EPOSP_SANITIZE)
        set(name ${target})
        if(ARG_NAME)
            set(name ${ARG_NAME})
        endif()
        math(EXPR last "${EPOSP_SANITIZER_SHARDS} - 1")
        foreach(shard RANGE ${last})
            add_test(NAME ${name}.shard${shard} COMMAND ${target})
            set_tests_properties(${name}.shard${shard} PROPERTIES LABELS ${label} ENVIRONMENT
                "${ARG_ENVIRONMENT};GTEST_TOTAL_SHARDS=${EPOSP_SANITIZER_SHARDS};GTEST_SHARD_INDEX=${shard}")
        endforeach()
    elseif(ARG_NAME)
        add_test(NAME ${ARG_NAME} COMMAND ${target})
        set_tests_properties(${ARG_NAME} PROPERTIES LABELS ${label} ENVIRONMENT "${ARG_ENVIRONMENT}")
    else()
        gtest_discover_tests(${target} PROPERTIES LABELS ${label} DISCOVERY_TIMEOUT 60)
    endif()
endfunction()
