#include "tools/realtime/two_bone_skin.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace quadtri::realtime {

TwoBoneSkin::TwoBoneSkin(std::vector<float> rest, float blendFraction) : rest_(std::move(rest)) {
    if (rest_.empty() || rest_.size() % 3 != 0)
        throw std::invalid_argument("TwoBoneSkin: the cage needs 3 floats per vertex and at least one vertex");
    if (!(blendFraction > 0.0f && blendFraction <= 1.0f))
        throw std::invalid_argument("TwoBoneSkin: the blend fraction must lie in (0, 1]");
    std::array<float, 3> lo{rest_[0], rest_[1], rest_[2]}, hi = lo;
    for (std::size_t i = 0; i < rest_.size(); i += 3)
        for (int c = 0; c < 3; ++c) {
            lo[c] = std::min(lo[c], rest_[i + c]);
            hi[c] = std::max(hi[c], rest_[i + c]);
        }
    std::array<int, 3> bySize{0, 1, 2};  // axes, longest first
    std::sort(bySize.begin(), bySize.end(), [&](int a, int b) { return hi[a] - lo[a] > hi[b] - lo[b]; });
    longAxis_ = bySize[0];
    bendAxis_ = bySize[1];
    const float length = hi[longAxis_] - lo[longAxis_];
    if (!(length > 0.0f)) throw std::invalid_argument("TwoBoneSkin: the cage's bounding box has no extent");
    for (int c = 0; c < 3; ++c) joint_[c] = 0.5f * (lo[c] + hi[c]);

    const float blendStart = joint_[longAxis_] - 0.5f * blendFraction * length;
    weights_.resize(rest_.size() / 3);
    for (std::size_t v = 0; v < weights_.size(); ++v) {
        const float s = std::clamp((rest_[3 * v + longAxis_] - blendStart) / (blendFraction * length), 0.0f, 1.0f);
        weights_[v] = s * s * (3.0f - 2.0f * s);
    }
}

void TwoBoneSkin::pose(float radians, float* out) const {
    // R - I for a turn about bendAxis_: in the plane of the other two axes (a, b), right-handed.
    const int a = (bendAxis_ + 1) % 3, b = (bendAxis_ + 2) % 3;
    const float cosMinus1 = std::cos(radians) - 1.0f, sine = std::sin(radians);
    for (std::size_t v = 0; v < weights_.size(); ++v) {
        const float* p = rest_.data() + 3 * v;
        float* q = out + 3 * v;
        const float w = weights_[v];
        const float da = p[a] - joint_[a], db = p[b] - joint_[b];
        q[bendAxis_] = p[bendAxis_];
        q[a] = p[a] + w * (cosMinus1 * da - sine * db);
        q[b] = p[b] + w * (sine * da + cosMinus1 * db);
    }
}

float bendAngle(double seconds, float maxRadians, double periodSeconds) {
    const double pi = 3.14159265358979323846;
    return float(0.5 * (1.0 - std::cos(2.0 * pi * seconds / periodSeconds))) * maxRadians;
}

}  // namespace quadtri::realtime
