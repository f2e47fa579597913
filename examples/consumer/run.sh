#!/usr/bin/env bash
# Builds and runs the two consumer projects end to end, each in a fresh temporary folder:
#   add_subdirectory/  quadtri built inside the consumer's own build (libraries only)
#   find_package/      quadtri configured and built on its own (libraries only), installed with
#                      cmake --install into a temporary prefix, then found there
# and compiles one-line programs with pkg-config against that prefix.
# Environment: QUADTRI_WITH_VULKAN (default ON), JOBS (default nproc), KEEP=1 keeps the folder;
# QUADTRI_REQUIRE_VULKAN=1 makes the programs fail without a Vulkan device.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
jobs=${JOBS:-$(nproc)}
vulkan=${QUADTRI_WITH_VULKAN:-ON}

work=$(mktemp -d)
if [ "${KEEP:-0}" = 1 ]; then echo "consumer: working in $work"; else trap 'rm -rf "$work"' EXIT; fi

cmake_args=(-DCMAKE_BUILD_TYPE=Release)
command -v ninja >/dev/null && cmake_args+=(-G Ninja)
# ccache when present: paths under the temporary folder are hashed relative to it, so reruns hit.
if command -v ccache >/dev/null; then
    cmake_args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    export CCACHE_BASEDIR="$work"
fi

step() { echo "consumer: $*"; }
# logged LOG WHAT COMMAND...: runs the command with its output appended to $work/LOG.log, says how
# long it took ("consumer:   build: 26 s"), and on failure prints the log and stops.
logged() {
    local log="$work/$1.log" what=$2 start=$SECONDS
    shift 2
    "$@" >>"$log" 2>&1 || { cat "$log"; echo "consumer: $what failed" >&2; exit 1; }
    echo "consumer:   $what: $((SECONDS - start)) s"
}

step "add_subdirectory: configure, build"
logged subdir configure cmake -S "$here/add_subdirectory" -B "$work/subdir" "${cmake_args[@]}" -DQUADTRI_WITH_VULKAN="$vulkan"
logged subdir build cmake --build "$work/subdir" -j "$jobs"

step "quadtri alone: configure, build, install into $work/prefix"
logged quadtri configure cmake -S "$repo" -B "$work/quadtri" "${cmake_args[@]}" -DQUADTRI_WITH_VULKAN="$vulkan" \
       -DQUADTRI_BUILD_TESTS=OFF -DQUADTRI_BUILD_BENCH=OFF -DQUADTRI_BUILD_TOOLS=OFF -DQUADTRI_BUILD_EXAMPLES=OFF
logged quadtri build cmake --build "$work/quadtri" -j "$jobs"
logged quadtri install cmake --install "$work/quadtri" --prefix "$work/prefix"
# Only the public headers: nothing of far/internal/, osd/internal/ or kernels/.
if find "$work/prefix/include" -path '*internal*' -o -path '*kernels*' | grep .; then
    echo "consumer: internal headers were installed (above)" >&2; exit 1
fi

step "find_package: configure, build against the prefix"
logged installed configure cmake -S "$here/find_package" -B "$work/installed" "${cmake_args[@]}" -DCMAKE_PREFIX_PATH="$work/prefix"
logged installed build cmake --build "$work/installed" -j "$jobs"

if ! command -v pkg-config >/dev/null; then
    step "pkg-config: not installed, skipped (Debian: pkgconf)"
else
    step "pkg-config: one-line programs against the prefix"
    export PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
    printf '%s\n' '#include <quadtri/quadtri.h>' \
        'int main() { return quadtri::toString(quadtri::Options{}.scheme)[0] == 0; }' >"$work/pc.cpp"
    # shellcheck disable=SC2046  # pkg-config's flags are meant to be split
    c++ -std=c++17 $(pkg-config --cflags quadtri) "$work/pc.cpp" -o "$work/pc" $(pkg-config --libs quadtri)
    "$work/pc"
    if [ -f "$work/prefix/lib/pkgconfig/quadtri-vulkan.pc" ]; then
        printf '%s\n' '#include <quadtri/osd/vulkan_context.h>' \
            'int main() { return quadtri::vkResultName(VK_SUCCESS)[0] == 0; }' >"$work/pc_vulkan.cpp"
        # shellcheck disable=SC2046
        c++ -std=c++17 $(pkg-config --cflags quadtri-vulkan) "$work/pc_vulkan.cpp" -o "$work/pc_vulkan" \
            $(pkg-config --libs quadtri-vulkan)
        "$work/pc_vulkan"
    fi
fi

for build in subdir installed; do
    step "run the $build consumer"
    "$work/$build/consumer"
done
step "all passed"
