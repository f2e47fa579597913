// The orbit camera and the light of a view: yaw and pitch about a target point at a distance,
// perspective, Vulkan's clip conventions (y down, depth 0..1).
#pragma once

#include <glm/glm.hpp>

namespace quadtri::render {

// The smallest-ish sphere around points (the box's centre, the farthest point's distance).
struct BoundingSphere {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
};
BoundingSphere boundingSphere(const float* xyz, int numPoints);

struct Camera {
    float yawDegrees = 30.0f;    // about the world's y axis; 0 looks along -z
    float pitchDegrees = 20.0f;  // up from the horizon
    float distance = 5.0f;       // from the target
    glm::vec3 target{0.0f};
    float fovYDegrees = 35.0f;

    // Target at the sphere's centre, the distance at which the sphere fills the narrower side of
    // a view of `aspect` (width / height) with a small margin.
    void frame(const BoundingSphere& sphere, float aspect);
    glm::vec3 eye() const;
    glm::mat4 view() const;
    // Projection to Vulkan clip space; near and far planes bracket a sphere of `radius` around
    // the target.
    glm::mat4 projection(float aspect, float radius) const;
};

struct Light {
    glm::vec3 direction{-0.3f, 0.5f, 0.8f};  // towards the light, in view space (follows the camera)
    glm::vec3 color{1.0f, 1.0f, 1.0f};
};

}  // namespace quadtri::render
