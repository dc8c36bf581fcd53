#!/usr/bin/env bash
# One entry point for newcomers and CI: installs what is missing, builds, runs.
#
#   ./eposp.sh demo       set up, build and run the demo
#   ./eposp.sh test       set up, build and run every test
#   ./eposp.sh sanitize   set up, build with AddressSanitizer + UBSan and run every test
#   ./eposp.sh build      set up and build only
#   ./eposp.sh setup      install the Debian packages that are missing, nothing else
#
# Packages come only from Debian's registry (apt-get), and only when missing: running it
# twice installs nothing the second time.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"

readonly BUILD_PACKAGES=(g++ cmake ninja-build libboost-dev libfmt-dev libcli11-dev
    libgtest-dev libgmock-dev libbenchmark-dev antlr4 libantlr4-runtime-dev)
# Independent tools that the interoperability tests and the demo talk to.
readonly TOOL_PACKAGES=(python3-can tshark)

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

# build DIR [cmake options...]
build() {
    local dir=$1
    shift
    log "building in $dir"
    cmake -S . -B "$dir" -G Ninja "$@" >/dev/null
    cmake --build "$dir"
}

run_tests() {
    local dir=$1
    log "running the tests in $dir"
    ctest --test-dir "$dir" --output-on-failure -j "$(nproc)"
}

case "${1:-}" in
setup) setup ;;
build) setup && build build ;;
demo) setup && build build && examples/bus-demo/run.sh build/device/eposp ;;
test) setup && build build && run_tests build ;;
sanitize)
    setup
    # Debug keeps assertions; -O1 keeps the suite fast. Only our own code is instrumented.
    build build-sanitize -DEPOSP_SANITIZE=ON -DEPOSP_BUILD_BENCHMARKS=OFF \
        -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g"
    run_tests build-sanitize
    ;;
*)
    sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'
    exit 1
    ;;
esac
