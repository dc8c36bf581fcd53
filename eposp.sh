#!/usr/bin/env bash
# One entry point for newcomers and CI: installs what is missing, builds, runs.
#
#   ./eposp.sh demo       set up, build and run the demo
#   ./eposp.sh test       set up, build and run every test
#   ./eposp.sh sanitize   set up, build with AddressSanitizer + UBSan and run every test
#   ./eposp.sh flakes [N] build, run two copies of the suite at once, N times in random order (3)
#   ./eposp.sh fuzz [S]   set up clang, build the libFuzzer targets, run each for S seconds (60)
#   ./eposp.sh difftest [M]  build st_difftest, run generated programs on every executor M minutes (10)
#   ./eposp.sh build      set up and build only
#   ./eposp.sh setup      install the Debian packages that are missing, nothing else
#
# Packages come only from Debian's registry (apt-get), and only when missing: running it
# twice installs nothing the second time.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"

readonly BUILD_PACKAGES=(g++ cmake ninja-build libboost-dev libfmt-dev libcli11-dev
    libgtest-dev libgmock-dev libbenchmark-dev antlr4 libantlr4-runtime-dev libyaml-cpp-dev
    libxbyak-dev nlohmann-json3-dev)
# Independent tools that the interoperability tests and the demo talk to (lcov: reads back the
# coverage tracefile of eposp test; xmllint: checks its JUnit report against a schema).
readonly TOOL_PACKAGES=(python3-can python3-serial tshark lcov libxml2-utils)
# Only for `fuzz`: clang and its sanitizer and libFuzzer runtimes.
readonly FUZZ_PACKAGES=(clang libclang-rt-14-dev)

log() { printf '\033[1m==> %s\033[0m\n' "$*" >&2; }

install_missing() {
    local missing=() package
    for package in "$@"; do
        dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q 'install ok installed' ||
            missing+=("$package")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    log "installing ${missing[*]}"
    local sudo=()
    [ "$(id -u)" -eq 0 ] || sudo=(sudo)
    export DEBIAN_FRONTEND=noninteractive
    "${sudo[@]}" apt-get update -qq
    "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

setup() { install_missing "${BUILD_PACKAGES[@]}" "${TOOL_PACKAGES[@]}"; }

# build DIR [cmake options...]. Line tables (-g1) are enough for backtraces and sanitizer
# reports; full debug info would cost a third more compile time. Configure a build directory
# of your own with -DCMAKE_BUILD_TYPE=Debug to step through the code in a debugger.
build() {
    local dir=$1
    shift
    log "building in $dir"
    cmake -S . -B "$dir" -G Ninja -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" "$@" >/dev/null
    cmake --build "$dir"
}

# Random order, so that a test that depends on another's leftovers fails here and not by chance.
run_tests() {
    local dir=$1
    log "running the tests in $dir"
    ctest --test-dir "$dir" --output-on-failure -j "$(nproc)" --schedule-random
}

# flakes N: two copies of the suite at once, each repeated N times in random order; a test that
# shares a file, a port or a timing assumption with another fails here.
flakes() {
    local repeats=$1 first second
    log "running two copies of the suite at once, $repeats times each"
    ctest --test-dir build -j "$(nproc)" --schedule-random --repeat until-fail:"$repeats" \
        --output-on-failure --output-log build/flakes-1.log >/dev/null &
    first=$!
    ctest --test-dir build -j "$(nproc)" --schedule-random --repeat until-fail:"$repeats" \
        --output-on-failure --output-log build/flakes-2.log >/dev/null &
    second=$!
    local status=0
    wait "$first" || { status=1; log "the first copy failed: build/flakes-1.log"; }
    wait "$second" || { status=1; log "the second copy failed: build/flakes-2.log"; }
    return "$status"
}

# fuzz SECONDS: each target in turn, one process, from its seed corpus; what it finds new goes to
# build-fuzz/corpus/<target>/, a crashing input to build-fuzz/artifacts/<target>/.
fuzz() {
    local seconds=$1 binary seeds name failed=()
    while read -r binary seeds; do
        name=$(basename "$seeds")
        log "fuzzing $name for $seconds s"
        mkdir -p "build-fuzz/corpus/$name" "build-fuzz/artifacts/$name"
        "$binary" -max_total_time="$seconds" -timeout=10 -print_final_stats=1 \
            -artifact_prefix="build-fuzz/artifacts/$name/" "build-fuzz/corpus/$name" "$seeds" ||
            failed+=("$name")
    done <build-fuzz/tests/fuzz/fuzz_targets.txt
    [ ${#failed[@]} -eq 0 ] || { log "failing inputs found by: ${failed[*]}"; return 1; }
}

case "${1:-}" in
setup) setup ;;
build) setup && build build ;;
demo)
    setup && build build
    examples/pick-and-place/run.sh build/device/eposp
    examples/two-axis/run.sh build/device/eposp
    examples/plc-basics/run.sh build/device/eposp
    examples/escon2-spindle/run.sh build/device/eposp
    log "the ST unit tests of examples/homing-then-move, with its drive simulated in virtual time"
    build/device/eposp test examples/homing-then-move/homing-then-move.st \
        examples/homing-then-move/tests/*_test.st --network examples/homing-then-move/network.yaml
    ;;
test) setup && build build && run_tests build ;;
flakes) setup && build build && flakes "${2:-3}" ;;
sanitize)
    setup
    # Debug keeps assertions; -O1 keeps the suite fast. Only our own code is instrumented.
    build build-sanitize -DEPOSP_SANITIZE=ON -DEPOSP_BUILD_BENCHMARKS=OFF \
        -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1"
    run_tests build-sanitize
    ;;
difftest)
    # New seeds each run (from the clock); a mismatch prints its seed and reduced program and
    # makes the exit status 1. Reproduce one with: build/tests/differential/st_difftest
    # --seeds 1 --from SEED (docs/testing.md, Differential testing).
    setup
    log "building st_difftest in build"
    cmake -S . -B build -G Ninja >/dev/null
    cmake --build build --target st_difftest
    build/tests/differential/st_difftest --minutes "${2:-10}" --from "$(date +%s)" "${@:3}"
    ;;
fuzz)
    setup && install_missing "${FUZZ_PACKAGES[@]}"
    log "building the fuzz targets in build-fuzz"
    cmake -S . -B build-fuzz -G Ninja -DEPOSP_BUILD_FUZZERS=ON -DCMAKE_CXX_COMPILER=clang++ \
        -DEPOSP_BUILD_BENCHMARKS=OFF -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" \
        >/dev/null
    cmake --build build-fuzz --target eposp_fuzzers
    fuzz "${2:-60}"
    ;;
*)
    sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//'
    exit 1
    ;;
esac
