// `quadtri view`: the interactive viewer (docs/viewer.md). It owns the window, the Vulkan
// instance and device (render::GpuDevice, handed to quadtri through VulkanContext::External),
// the swapchain and the UI; each frame it poses the cage, evaluates the surface into the
// buffers the draw reads, and draws one or two viewports with the panel over them.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tools/render/gpu_device.h"
#include "tools/render/image.h"
#include "tools/view/choices.h"
#include "tools/view/core/document.h"
#include "tools/view/imgui_layer.h"
#include "tools/view/core/picking.h"
#include "tools/view/core/script.h"
#include "tools/view/swapchain.h"
#include "tools/view/view_command.h"
#include "tools/view/viewed_surface.h"
#include "tools/view/window.h"

namespace quadtri::view {

class Viewer {
public:
    // Opens the window and the device, loads the mesh. WindowError / VulkanError / the file's
    // errors escape: the caller reports them and exits with status 2.
    explicit Viewer(const ViewerArgs& args);
    ~Viewer();

    // Frames until the window closes (after the unsaved-edits prompt), or the script's commands
    // one per frame then quit. Returns the exit status.
    int run();

    // From GLFW's callbacks: the wheel zooms; a dropped file is loaded.
    void onScroll(double steps);
    void onDrop(const std::string& path);

private:
    int runFrames();
    // One frame: rebuild what the choices changed, input, the real-time loop, draw. With
    // `screenshot` the frame is drawn without the panel and copied out.
    void frame(render::Image* screenshot, bool withPanel = false);
    void rebuild();
    void handleInput();
    void pick(glm::vec2 cursor, bool add);
    void drawPanel();
    void drawFilePanel();
    void drawSurfacePanel();
    void drawDisplayPanel();
    void drawSelectionPanel();
    void drawTimings();
    void drawConfirmation();
    void frameMesh();
    // A viewport's rectangle: the window, or its left / right half when comparing.
    int viewportCount() const;
    // The panel's width and the margin it keeps from the window's right edge, in pixels.
    static constexpr float kPanelWidth = 330.0f, kPanelMargin = 8.0f;
    static constexpr uint32_t kPanelReserve = uint32_t(kPanelWidth + kPanelMargin);
    VkRect2D viewport(int index) const;
    glm::mat4 viewProjection(int index) const;
    void requestLoad(const std::string& path);  // through the unsaved-edits prompt
    void closeRequested();                      // the same for quitting
    void load(const std::string& path);         // shows the error and keeps the mesh on failure
    void saveScreenshot(const std::string& path, bool withPanel = false);
    // A PNG or JPEG for textured shading; a failure shows in message_ and keeps the old one.
    void loadTexture(const std::string& path);
    void runCommand(const ScriptCommand& command, const std::string& script);
    // The selection's sharpness set in the document and queued as an edit of the surfaces.
    void editSelection(float sharpness);
    // The queued edits applied to every surface in place (a surface that refuses one is rebuilt).
    void applyEdits();

    // Declared in the order of creation: each goes before what it was made from.
    ViewerArgs args_;
    Document document_;
    std::optional<Window> window_;
    std::optional<render::GpuDevice> gpu_;
    std::optional<WindowSurface> surface_;
    std::optional<Swapchain> swapchain_;
    std::optional<ImGuiLayer> ui_;
    std::optional<render::Image> texture_;
    std::vector<std::unique_ptr<ViewedSurface>> surfaces_;  // one per viewport

    Choices choices_;
    render::ViewSettings view_;
    bool needsRebuild_ = true, needsUpdate_ = true, quit_ = false;
    std::string message_;  // the last error, shown in the panel

    bool deform_ = false;
    float speed_ = 1.0f;
    double motionSeconds_ = 0.0;
    double lastFrameTime_ = 0.0;
    realtime::PhaseTimes times_;
    double drawMs_ = 0.0;
    TagEdits pendingEdits_;  // made since the last frame
    double editMs_ = -1.0;   // the last edit's update of the surfaces, -1 before any

    // Mouse: a drag rotates (left) or pans (right, middle); a left click without a drag picks.
    bool dragging_ = false;
    int dragButton_ = -1;
    glm::vec2 pressAt_{0.0f}, lastCursor_{0.0f};
    bool moved_ = false;

    enum class Pending { None, Quit, Load, Screenshot } pending_ = Pending::None;
    bool wantsScreenshot_ = false;
    std::string pendingPath_;
    std::array<char, 1024> loadPath_{}, savePath_{}, shotPath_{}, texturePath_{};
};

}  // namespace quadtri::view
