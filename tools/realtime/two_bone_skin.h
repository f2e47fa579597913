// Two-bone linear-blend skinning of a cage along its longest axis: the demo's deformation
// (docs/realtime_loop.md, "The skin"). Bone 1 holds the first half of the cage still; bone 2 turns
// the second half about an axis through the joint, and a smooth blend region around the joint
// mixes the two.
#pragma once

#include <array>
#include <vector>

namespace quadtri::realtime {

class TwoBoneSkin {
public:
    // The cage's rest positions (3 floats per vertex). The bones run along the longest side of
    // its bounding box, joined at the middle; the blend region is `blendFraction` of that side's
    // length, centred on the joint. The bend turns about the box's second-longest side, so the
    // cage bends in the plane of its longest and shortest sides. std::invalid_argument on an
    // empty cage, a size that is not a multiple of 3 or a flat box, or a fraction outside (0, 1].
    explicit TwoBoneSkin(std::vector<float> rest, float blendFraction = 0.2f);

    int numVertices() const { return int(rest_.size() / 3); }
    const std::vector<float>& rest() const { return rest_; }
    // Per vertex: bone 2's weight (bone 1 has 1 minus it), 0 before the blend region, 1 after it,
    // a smoothstep in between.
    const std::vector<float>& weights() const { return weights_; }
    int longAxis() const { return longAxis_; }  // 0, 1, 2: x, y, z
    int bendAxis() const { return bendAxis_; }
    const std::array<float, 3>& joint() const { return joint_; }

    // The cage posed with bone 2 turned by `radians` about the bend axis through the joint, into
    // `out` (3 floats per vertex): p + w (R - I)(p - joint), the blend of p and R(p - joint) +
    // joint written as a displacement, so that angle 0 and weight 0 give p exactly.
    void pose(float radians, float* out) const;

private:
    std::vector<float> rest_;
    std::vector<float> weights_;
    int longAxis_ = 0, bendAxis_ = 1;
    std::array<float, 3> joint_{};
};

// The demo's motion: the bend angle at time `seconds`, from 0 (the rest pose, at t = 0) up to
// `maxRadians` and back, once per `periodSeconds`, eased at both ends (a raised cosine).
float bendAngle(double seconds, float maxRadians = 1.75f, double periodSeconds = 2.0);

}  // namespace quadtri::realtime
