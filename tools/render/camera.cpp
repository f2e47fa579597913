#include "tools/render/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace quadtri::render {

BoundingSphere boundingSphere(const float* xyz, int numPoints) {
    if (numPoints <= 0) return {};
    glm::vec3 lo(xyz[0], xyz[1], xyz[2]), hi = lo;
    for (int i = 1; i < numPoints; ++i) {
        const glm::vec3 p(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
        lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    BoundingSphere s{(lo + hi) * 0.5f, 0.0f};
    for (int i = 0; i < numPoints; ++i)
        s.radius = std::max(s.radius, glm::length(glm::vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]) - s.center));
    if (s.radius <= 0.0f) s.radius = 1.0f;
    return s;
}

void Camera::frame(const BoundingSphere& sphere, float aspect) {
    target = sphere.center;
    const float halfY = glm::radians(fovYDegrees) * 0.5f;
    const float halfX = std::atan(std::tan(halfY) * aspect);
    distance = 1.08f * sphere.radius / std::sin(std::min(halfX, halfY));
}

glm::vec3 Camera::eye() const {
    const float yaw = glm::radians(yawDegrees), pitch = glm::radians(pitchDegrees);
    const glm::vec3 back(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
    return target + distance * back;
}

glm::mat4 Camera::view() const {
    // Straight up or down the world's y axis has no defined roll: keep the pitch off the poles.
    return glm::lookAt(eye(), target, glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 Camera::projection(float aspect, float radius) const {
    const float nearPlane = std::max(distance - 1.5f * radius, distance * 1e-3f);
    const float farPlane = distance + 1.5f * radius;
    glm::mat4 p = glm::perspectiveRH_ZO(glm::radians(fovYDegrees), aspect, nearPlane, farPlane);
    p[1][1] = -p[1][1];  // Vulkan's clip y points down
    return p;
}

}  // namespace quadtri::render
