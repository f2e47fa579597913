#!/usr/bin/env bash
# quadtri's two commands:
#   ./run.sh demo   install missing Debian packages, build (Release, build/), refine a bundled mesh
#   ./run.sh test   the same set-up, then every test through ctest
# Environment: BUILD_DIR (default build), CMAKE_ARGS (extra configure flags), JOBS.
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(cmake ninja-build g++ libgtest-dev libgmock-dev libeigen3-dev libosd-dev libcli11-dev libtbb-dev libvulkan-dev mesa-vulkan-drivers glslang-tools vulkan-validationlayers)
BUILD_DIR=${BUILD_DIR:-build}
JOBS=${JOBS:-$(nproc)}

install_missing() {
    local missing=()
    for p in "${PACKAGES[@]}"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    if [ "$(id -u)" -ne 0 ]; then
        echo "run.sh: missing Debian packages: ${missing[*]}" >&2
        echo "run.sh: run as root, or install them first: sudo apt-get install ${missing[*]}" >&2
        exit 1
    fi
    echo "run.sh: installing ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build() {
    cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release ${CMAKE_ARGS:-}
    cmake --build "$BUILD_DIR" -j "$JOBS"
}

case "${1:-}" in
demo)
    install_missing
    build
    "$BUILD_DIR/bin/quadtri" demo data/mixed_torus.obj --levels 3 --out-dir "$BUILD_DIR/demo"
    ;;
test)
    install_missing
    build
    status=0
    ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS" | tee "$BUILD_DIR/ctest.out" || status=$?
    # ctest lists skipped tests without their reason: print each one's reason from the log, then
    # the totals once more so they stay the last line.
    log="$BUILD_DIR/Testing/Temporary/LastTest.log"
    reasons=$(awk '/: Skipped$/ {getline reason; want=1; next}
                   want && /^\[  SKIPPED \]/ {sub(/ \(.*/, ""); print "  " $4 ": " reason; want=0}' "$log" 2>/dev/null || true)
    if [ -n "$reasons" ]; then
        skipped=$(printf '%s\n' "$reasons" | wc -l)
        echo "Skipped, with the reason each test gave:"
        printf '%s\n' "$reasons"
        read -r failed total < <(sed -n 's/.* \([0-9]*\) tests failed out of \([0-9]*\).*/\1 \2/p' "$BUILD_DIR/ctest.out")
        echo "ctest: $((total - failed - skipped)) passed, $failed failed, $skipped skipped"
    fi
    exit $status
    ;;
*)
    echo "usage: ./run.sh demo | test" >&2
    exit 2
    ;;
esac
