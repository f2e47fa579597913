// The viewer's mouse and keyboard: the orbit camera (drag to rotate or pan, wheel to zoom, F to
// frame) and picking on a click (docs/viewer.md, "Picking").
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>

#include "tools/view/viewer.h"

namespace quadtri::view {

namespace {

constexpr float kPickEdgePixels = 6.0f, kPickPointPixels = 8.0f;

}  // namespace

void Viewer::onScroll(double steps) {
    if (ui_ && ui_->wantsMouse()) return;
    view_.camera.distance *= float(std::pow(0.9, steps));
}

void Viewer::handleInput() {
    GLFWwindow* w = window_->handle();
    double x = 0, y = 0;
    glfwGetCursorPos(w, &x, &y);
    // Window coordinates to framebuffer pixels (they differ on high-density displays).
    int ww = 1, wh = 1;
    glfwGetWindowSize(w, &ww, &wh);
    const VkExtent2D fb = swapchain_->extent();
    const glm::vec2 cursor(float(x) * float(fb.width) / float(std::max(ww, 1)),
                           float(y) * float(fb.height) / float(std::max(wh, 1)));
    const bool uiMouse = ui_->wantsMouse();
    const int buttons[3] = {GLFW_MOUSE_BUTTON_LEFT, GLFW_MOUSE_BUTTON_RIGHT, GLFW_MOUSE_BUTTON_MIDDLE};
    if (!dragging_) {
        for (int b : buttons)
            if (!uiMouse && glfwGetMouseButton(w, b) == GLFW_PRESS) {
                dragging_ = true, dragButton_ = b, moved_ = false;
                pressAt_ = lastCursor_ = cursor;
                break;
            }
    } else if (glfwGetMouseButton(w, dragButton_) == GLFW_RELEASE) {
        if (dragButton_ == GLFW_MOUSE_BUTTON_LEFT && !moved_) {
            const bool shift = glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                               glfwGetKey(w, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
            pick(cursor, shift);
        }
        dragging_ = false;
    } else {
        const glm::vec2 d = cursor - lastCursor_;
        lastCursor_ = cursor;
        moved_ = moved_ || glm::length(cursor - pressAt_) > 3.0f;
        if (moved_ && dragButton_ == GLFW_MOUSE_BUTTON_LEFT) {
            view_.camera.yawDegrees -= 0.4f * d.x;
            view_.camera.pitchDegrees = std::clamp(view_.camera.pitchDegrees + 0.4f * d.y, -89.0f, 89.0f);
        } else if (moved_) {
            // One pixel moves the target by one pixel's size at the target's depth.
            const float pixel = 2.0f * view_.camera.distance * std::tan(glm::radians(view_.camera.fovYDegrees) * 0.5f) /
                                float(std::max(fb.height, 1u));
            const glm::mat4 v = view_.camera.view();
            const glm::vec3 right(v[0][0], v[1][0], v[2][0]), up(v[0][1], v[1][1], v[2][1]);
            view_.camera.target += pixel * (-d.x * right + d.y * up);
        }
    }
    if (!ui_->wantsKeyboard() && glfwGetKey(w, GLFW_KEY_F) == GLFW_PRESS) frameMesh();
}

void Viewer::pick(glm::vec2 cursor, bool add) {
    for (int i = 0; i < viewportCount(); ++i) {
        const VkRect2D r = viewport(i);
        if (cursor.x < float(r.offset.x) || cursor.x >= float(r.offset.x) + float(r.extent.width)) continue;
        const ViewedSurface& surface = *surfaces_[std::size_t(i)];
        if (!surface.ready()) return;
        const std::vector<ScreenPoint> points =
            projectPoints(viewProjection(i), surface.cage().data(), int(surface.cage().size() / 3),
                          glm::vec2(float(r.offset.x), float(r.offset.y)),
                          glm::vec2(float(r.extent.width), float(r.extent.height)));
        // A vertex wins near it: every edge of the vertex is near there too.
        const int vertex = nearestPoint(points, cursor, kPickPointPixels);
        const int edge = vertex < 0 ? nearestEdge(points, surface.edges(), cursor, kPickEdgePixels) : -1;
        if (vertex >= 0) {
            document_.selectVertex(vertex, add);
            view_.showPoints = true;  // a selected vertex shows as a point
        }
        else if (edge >= 0)
            document_.selectEdge(int(surface.edges()[2 * std::size_t(edge)]), int(surface.edges()[2 * std::size_t(edge) + 1]), add);
        else if (!add)
            document_.clearSelection();
        needsUpdate_ = true;
        return;
    }
}

}  // namespace quadtri::view
