#!/usr/bin/env bash
# Renders the pictures of docs/rendering.md with `quadtri render` (docs/rendering.md):
#   tools/render_pictures.sh [QUADTRI [OUT_DIR]]
# QUADTRI defaults to build/bin/quadtri, OUT_DIR to docs/images. Needs a Vulkan device (lavapipe
# will do: a few seconds per picture).
set -euo pipefail
cd "$(dirname "$0")/.."
QUADTRI=${1:-build/bin/quadtri}
OUT=${2:-docs/images}
mkdir -p "$OUT"
render() { "$QUADTRI" render --supersample 3 "$@"; }

# The README's picture: the mixed torus under Catmull-Clark and Schaefer-Warren.
render data/mixed_torus.obj --level 4 --compare catmull-clark,schaefer-warren --size 560x440 --yaw 20 --pitch 35 \
    --shading reflection-lines --stripes 14 -o "$OUT/readme_torus.png"

# The mixed torus under the three mixed schemes: Catmull-Clark ripples over the triangles,
# Stam-Loop bends the stripes at the seam, Schaefer-Warren keeps them straight.
SCHEMES=catmull-clark,stam-loop,schaefer-warren
render data/mixed_torus.obj --level 4 --compare "$SCHEMES" --size 520x440 --yaw 20 --pitch 35 \
    --shading reflection-lines --stripes 14 -o "$OUT/torus_reflection_lines.png"
render data/mixed_torus.obj --level 4 --compare "$SCHEMES" --size 520x440 --yaw 20 --pitch 35 \
    --shading mean-curvature -o "$OUT/torus_mean_curvature.png"
render data/mixed_torus.obj --level 3 --size 520x440 --yaw 20 --pitch 35 --shading face-type --cage \
    --label "orange: from triangles, blue: from quads" -o "$OUT/torus_face_type.png"

# The capped cylinder's bottom rim at sharpness 0, 1, 2.5 and 10 (infinite), cage coloured by
# sharpness.
for s in 0 1 2.5 10; do
    render tests/meshes/mixed/cylinder_capped_creased.obj --level 4 --crease-sharpness "$s" --cage \
        --size 400x320 --yaw 125 --pitch 20 --light-dir 0.6,0.4,0.7 --label "rim sharpness $s" -o "$OUT/cylinder_crease_$s.png"
done

# Catmark-butterfly interpolates its control points on the triangles; Schaefer-Warren does not.
render data/mixed_torus.obj --level 3 --compare catmark-butterfly,schaefer-warren --points --cage \
    --size 520x440 --yaw 20 --pitch 35 -o "$OUT/torus_butterfly_points.png"
echo "render_pictures.sh: pictures in $OUT"
