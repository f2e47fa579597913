#!/usr/bin/env bash
# quadtri's commands:
#   ./run.sh demo   install missing Debian packages, build the quadtri CLI only (Release, build/), time
#                   the real-time loop on the bundled cage, then the pictures and the viewer
#   ./run.sh test   the same set-up, then every test through ctest
#   ./run.sh fuzz [obj|topology]   also clang; build the libFuzzer targets (build-fuzz/), run each
# Environment: BUILD_DIR (default build), CMAKE_ARGS (extra configure flags), JOBS; for fuzz:
# FUZZ_BUILD_DIR (default build-fuzz), FUZZ_SECONDS per target (default 60), FUZZ_ARGS (more
# libFuzzer flags, e.g. -jobs=4 -workers=4).
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(cmake ninja-build g++ libgtest-dev libgmock-dev libeigen3-dev libosd-dev libcli11-dev libtbb-dev libvulkan-dev mesa-vulkan-drivers glslang-tools vulkan-validationlayers pkgconf libtinygltf-dev libmeshoptimizer-dev libstb-dev libglm-dev)
# The viewer (window, UI) and its test under Xvfb.
PACKAGES+=(libglfw3-dev libimgui-dev xvfb xauth)
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

# build [TARGET...]: configure, then build the targets (default: everything).
build() {
    cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release ${CMAKE_ARGS:-}
    cmake --build "$BUILD_DIR" -j "$JOBS" ${1:+--target "$@"}
}

DEMO_CAGE=data/mixed_limb.obj

# Whether the built quadtri has the subcommand $1 (its --help lists it).
has_command() {
    "$BUILD_DIR/bin/quadtri" --help | grep -E "^ +$1 " >/dev/null  # grep reads it all: no SIGPIPE
}

# The pictures of docs/rendering.md (tools/render_pictures.sh, `quadtri render`) into $BUILD_DIR/demo/.
demo_pictures() {
    tools/render_pictures.sh "$BUILD_DIR/bin/quadtri" "$BUILD_DIR/demo"
}

# The viewer on the bundled cage with a display (DISPLAY or WAYLAND_DISPLAY), else its command.
demo_viewer() {
    local view=("$BUILD_DIR/bin/quadtri" view "$DEMO_CAGE")
    if ! has_command view; then
        echo "run.sh: this quadtri has no viewer yet; once it has, look at the cage with: ${view[*]}"
    elif [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
        "${view[@]}"
    else
        echo "run.sh: no display (DISPLAY, WAYLAND_DISPLAY unset); to look at the cage: ${view[*]}"
    fi
}

case "${1:-}" in
demo)
    install_missing
    build quadtri_cli  # the tests and bench are ./run.sh test's
    "$BUILD_DIR/bin/quadtri" demo "$DEMO_CAGE" --level 3
    demo_pictures
    demo_viewer
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
fuzz)
    PACKAGES+=(clang libclang-rt-14-dev)
    install_missing
    FUZZ_BUILD_DIR=${FUZZ_BUILD_DIR:-build-fuzz}
    targets=("${@:2}")
    [ ${#targets[@]} -eq 0 ] && targets=(obj topology)
    cmake -S . -B "$FUZZ_BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
          -DQUADTRI_FUZZ=ON ${CMAKE_ARGS:-}
    cmake --build "$FUZZ_BUILD_DIR" -j "$JOBS" --target "${targets[@]/#/quadtri_fuzz_}"
    status=0
    for target in "${targets[@]}"; do
        # libFuzzer adds what it finds to its corpus directory: work on a copy, keep the checked-in one.
        work="$FUZZ_BUILD_DIR/fuzz/$target"
        rm -rf "$work"
        mkdir -p "$work/artifacts"
        cp -r "tests/fuzz/corpus/$target" "$work/corpus"
        echo "run.sh: fuzzing $target for ${FUZZ_SECONDS:-60} s"
        if "$FUZZ_BUILD_DIR/bin/fuzz_$target" -max_total_time="${FUZZ_SECONDS:-60}" -timeout=10 -rss_limit_mb=2048 \
                -artifact_prefix="$work/artifacts/" ${FUZZ_ARGS:-} "$work/corpus" >"$work/fuzz.log" 2>&1; then
            grep -E '^(Done|#[0-9]+.*DONE)' "$work/fuzz.log" || tail -n 3 "$work/fuzz.log"
        else
            status=1
            tail -n 60 "$work/fuzz.log"
        fi
        if [ -n "$(ls -A "$work/artifacts")" ]; then
            status=1
            echo "run.sh: fuzz_$target failed; reproduce with: $FUZZ_BUILD_DIR/bin/fuzz_$target FILE" >&2
            ls -d "$work/artifacts/"* >&2
        fi
    done
    exit $status
    ;;
*)
    echo "usage: ./run.sh demo | test | fuzz [obj|topology]" >&2
    exit 2
    ;;
esac
