#include "tools/view/viewer.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ostream>

#include "tools/view/core/cage_edits.h"

namespace quadtri::view {

namespace {

using Clock = std::chrono::steady_clock;
constexpr std::array<float, 4> kBackground{0.13f, 0.14f, 0.16f, 1.0f};

// A script's frames are this far apart, whatever they take to draw: its animation and Dear
// ImGui's fades (the modal prompt's veil) then look the same on every machine.
constexpr double kScriptFrameSeconds = 1.0 / 60.0;

double seconds() { return std::chrono::duration<double>(Clock::now().time_since_epoch()).count(); }

Viewer& viewerOf(GLFWwindow* window) { return *static_cast<Viewer*>(glfwGetWindowUserPointer(window)); }

void scrolled(GLFWwindow* window, double, double dy) { viewerOf(window).onScroll(dy); }

void dropped(GLFWwindow* window, int count, const char** paths) {
    if (count > 0) viewerOf(window).onDrop(paths[0]);
}

render::GpuDeviceOptions windowDevice() {
    render::GpuDeviceOptions options;
    options.instanceExtensions = Window::requiredInstanceExtensions();
    options.deviceExtensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
    options.canPresent = &Window::canPresent;
    return options;
}

void copyInto(std::array<char, 1024>& buffer, const std::string& text) {
    std::snprintf(buffer.data(), buffer.size(), "%s", text.c_str());
}

}  // namespace

Viewer::Viewer(const ViewerArgs& args) : args_(args) {
    document_.load(args.mesh.input);  // a bad file before any window opens
    window_.emplace(args.width, args.height, "quadtri view");
    glfwSetWindowUserPointer(window_->handle(), this);
    gpu_.emplace(windowDevice());
    surface_.emplace(*window_, gpu_->instance());
    swapchain_.emplace(gpu_->context(), surface_->handle());
    // The swapchain exists once a frame has begun: ImGui needs its image count.
    swapchain_->beginFrame(window_->framebufferSize());
    swapchain_->beginRenderPass(kBackground);
    swapchain_->endFrame(nullptr);
    // Ours first: ImGui's callbacks chain to them.
    glfwSetScrollCallback(window_->handle(), &scrolled);
    glfwSetDropCallback(window_->handle(), &dropped);
    ui_.emplace(window_->handle(), gpu_->context(), swapchain_->renderPass(), swapchain_->minImageCount(),
                std::max(swapchain_->imageCount(), swapchain_->minImageCount()));
    if (!args.texture.empty()) texture_ = render::readImage(args.texture);

    const io::ObjMesh& mesh = document_.mesh();
    choices_.scheme = args.mesh.scheme.value_or(Options().scheme);
    choices_.boundary = args.mesh.boundary.value_or(mesh.boundary.value_or(Options().boundary));
    choices_.creaseMethod = args.mesh.creaseMethod.value_or(mesh.creaseMethod.value_or(Options().creaseMethod));
    choices_.uvs = args.mesh.uvInterpolation.value_or(Options().fvarLinearInterpolation);
    choices_.level = args.level;
    choices_.evaluator = args.evaluator;
    choices_.tables = args.tables;
    view_.showCage = true;
    if (mesh.hasUVs()) view_.shading = render::Shading::Textured;
    copyInto(loadPath_, args.mesh.input);
    copyInto(savePath_, args.mesh.input);
    copyInto(shotPath_, "view.png");
    rebuild();
    if (!message_.empty()) throw std::runtime_error(message_);  // the file given cannot be shown
    frameMesh();
}

Viewer::~Viewer() {
    if (gpu_) vkDeviceWaitIdle(gpu_->device());
}

int Viewer::run() {
    try {
        return runFrames();
    } catch (const VulkanError&) {
        // The device is gone (lost, out of memory): the edits are written beside the file first.
        if (document_.unsaved()) {
            const std::string rescue = document_.path() + ".unsaved.obj";
            try {
                writeCage(rescue, document_.mesh());
                std::fprintf(stderr, "quadtri: the unsaved edits are in %s\n", rescue.c_str());
            } catch (const std::exception& e) {
                std::fprintf(stderr, "quadtri: the unsaved edits could not be written: %s\n", e.what());
            }
        }
        throw;
    }
}

int Viewer::runFrames() {
    lastFrameTime_ = seconds();
    if (!args_.script.empty()) {
        const std::vector<ScriptCommand> commands = readScript(args_.script);
        std::string after = args_.script + ": ";  // the command whose change the frame shows
        for (const ScriptCommand& command : commands) {
            frame(nullptr);
            if (!message_.empty()) throw ScriptError(after + message_);
            if (command.verb == ScriptVerb::Quit) break;
            runCommand(command, args_.script);
            after = args_.script + ":" + std::to_string(command.line) + ": ";
            if (quit_) return 0;  // `close` without unsaved edits
        }
        if (document_.unsaved())
            std::fprintf(stderr, "quadtri: the script ends with edits it did not save\n");
        return 0;
    }
    while (!quit_) {
        if (window_->shouldClose()) {
            window_->setShouldClose(false);
            closeRequested();
        }
        if (quit_) break;
        frame(nullptr);
        if (wantsScreenshot_) {
            wantsScreenshot_ = false;
            try {
                saveScreenshot(shotPath_.data());
            } catch (const std::exception& e) {
                message_ = e.what();
            }
        }
    }
    return 0;
}

void Viewer::onDrop(const std::string& path) { requestLoad(path); }

void Viewer::closeRequested() {
    if (document_.unsaved())
        pending_ = Pending::Quit;
    else
        quit_ = true;
}

void Viewer::requestLoad(const std::string& path) {
    if (document_.unsaved()) {
        pending_ = Pending::Load;
        pendingPath_ = path;
        return;
    }
    load(path);
}

void Viewer::load(const std::string& path) {
    const Document previous = document_;
    try {
        document_.load(path);  // keeps the document as it was when the file fails
    } catch (const io::ObjError& e) {
        message_ = e.what();
        return;
    }
    needsRebuild_ = true;
    rebuild();
    if (!message_.empty()) {
        // A file that reads but does not refine: back to the mesh shown, with the reason.
        const std::string why = message_;
        document_ = previous;
        needsRebuild_ = true;
        rebuild();
        message_ = why;
        return;
    }
    copyInto(savePath_, path);
    frameMesh();
}

int Viewer::viewportCount() const { return choices_.compare ? 2 : 1; }

VkRect2D Viewer::viewport(int index) const {
    const VkExtent2D size = swapchain_->extent();
    if (viewportCount() == 1) return {{0, 0}, size};  // the panel floats over its right side
    // Side by side, both views share what the panel leaves free (it starts at the right edge), so
    // that neither hides behind it.
    const uint32_t free = size.width - std::min(kPanelReserve, size.width / 3);
    const uint32_t half = free / 2;
    return {{int32_t(index * half), 0}, {index == 0 ? half : free - half, size.height}};
}

glm::mat4 Viewer::viewProjection(int index) const {
    const VkRect2D r = viewport(index);
    const float aspect = float(r.extent.width) / float(std::max(r.extent.height, 1u));
    return view_.camera.projection(aspect, view_.sceneRadius) * view_.camera.view();
}

void Viewer::frameMesh() {
    const io::ObjMesh& mesh = document_.mesh();
    const render::BoundingSphere sphere = render::boundingSphere(mesh.positions.data(), mesh.numVertices());
    const VkRect2D r = viewport(0);
    view_.camera.frame(sphere, float(r.extent.width) / float(std::max(r.extent.height, 1u)));
    // Room for the bend of the real-time loop.
    view_.sceneRadius = 1.5f * sphere.radius;
}

void Viewer::editSelection(float sharpness) {
    document_.setSelectionSharpness(sharpness);
    sharpness = std::min(sharpness, kInfiniteSharpness);  // as the document keeps it
    for (const auto& [a, b] : document_.selectedEdges()) pendingEdits_.setCrease(a, b, sharpness);
    for (int v : document_.selectedVertices()) pendingEdits_.setCorner(v, sharpness);
}

void Viewer::applyEdits() {
    if (pendingEdits_.empty()) return;
    if (!needsRebuild_) {  // a rebuild reads the document, edits and all
        double ms = 0.0;
        try {
            for (const auto& surface : surfaces_) ms += surface->edit(pendingEdits_);
            editMs_ = ms;
        } catch (const VulkanError&) {
            throw;  // the device: not something a rebuild can fix
        } catch (const std::exception&) {
            needsRebuild_ = true;  // the document's tags go through the descriptor's rules instead
        }
        needsUpdate_ = true;
    }
    pendingEdits_.clear();
}

void Viewer::rebuild() {
    applyEdits();
    if (!needsRebuild_) return;
    const std::size_t count = std::size_t(viewportCount());
    const bool reframe = !surfaces_.empty() && surfaces_.size() != count;  // the viewports' shape changed
    while (surfaces_.size() < count)
        surfaces_.push_back(std::make_unique<ViewedSurface>(gpu_->context(), swapchain_->renderPass(),
                                                            texture_ ? &*texture_ : nullptr));
    surfaces_.resize(count);
    try {
        for (std::size_t i = 0; i < count; ++i) {
            const Scheme scheme = i == 0 ? choices_.scheme : *choices_.compare;
            const Options options = cli::makeOptions(meshArgsOf(choices_, scheme), document_.mesh());
            surfaces_[i]->rebuild(document_.mesh(), options, choices_.level, choices_.evaluator, choices_.tables);
        }
        message_.clear();
    } catch (const VulkanError&) {
        throw;  // the device: not something the panel can fix
    } catch (const std::exception& e) {
        message_ = document_.path() + ": " + e.what();
    }
    needsRebuild_ = false;
    needsUpdate_ = true;
    if (reframe) frameMesh();
}

void Viewer::frame(render::Image* screenshot, bool withPanel) {
    glfwPollEvents();
    rebuild();
    handleInput();
    const bool scripted = !args_.script.empty();
    const double now = scripted ? lastFrameTime_ + kScriptFrameSeconds : seconds();
    if (deform_) motionSeconds_ += (now - lastFrameTime_) * double(speed_);
    lastFrameTime_ = now;
    const bool curvature = view_.shading == render::Shading::MeanCurvature;
    if (choices_.adaptive)
        for (int i = 0; i < viewportCount() && std::size_t(i) < surfaces_.size(); ++i)
            needsUpdate_ |= surfaces_[std::size_t(i)]->adapt(view_, viewport(i).extent, choices_.pixelsPerSegment);
    if (deform_ || needsUpdate_) {
        const float angle = deform_ ? realtime::bendAngle(motionSeconds_) : 0.0f;
        times_ = {};
        for (auto& surface : surfaces_) {
            const realtime::PhaseTimes t =
                surface->update(angle, document_.selectedEdges(), document_.selectedVertices(), curvature);
            times_.deformMs += t.deformMs, times_.evaluateMs += t.evaluateMs, times_.normalsMs += t.normalsMs;
        }
        needsUpdate_ = false;
    }

    const Clock::time_point drawStart = Clock::now();
    if (!swapchain_->beginFrame(window_->framebufferSize())) {
        glfwWaitEventsTimeout(0.05);  // minimized or resized: try again
        return;
    }
    ui_->newFrame(scripted ? float(kScriptFrameSeconds) : 0.0f);
    drawPanel();
    VkCommandBuffer cmd = swapchain_->commandBuffer();
    // The evaluators' writes (earlier submissions) before the vertex shaders read them.
    auto barrier = detail::vkStruct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_HOST_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_HOST_BIT,
                         VK_PIPELINE_STAGE_VERTEX_SHADER_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
    swapchain_->beginRenderPass(kBackground);
    // One curvature colour range for both viewports, so that they compare.
    render::ViewSettings view = view_;
    view.curvatureRange = 1e-6f;
    for (const auto& surface : surfaces_) view.curvatureRange = std::max(view.curvatureRange, surface->curvatureRange());
    for (int i = 0; i < viewportCount(); ++i) {
        const VkRect2D r = viewport(i);
        surfaces_[std::size_t(i)]->renderer().record(cmd, r, view);
    }
    ui_->render(cmd, screenshot == nullptr || withPanel);
    swapchain_->endFrame(screenshot);
    drawMs_ = std::chrono::duration<double, std::milli>(Clock::now() - drawStart).count();
}

void Viewer::loadTexture(const std::string& path) {
    try {
        texture_ = render::readImage(path);
    } catch (const std::runtime_error& e) {
        message_ = e.what();
        return;
    }
    for (auto& surface : surfaces_) surface->renderer().setTexture(&*texture_);
    view_.shading = render::Shading::Textured;
}

void Viewer::saveScreenshot(const std::string& path, bool withPanel) {
    render::Image image;
    // A swapchain gone out of date draws nothing: the next frame makes a new one.
    for (int attempt = 0; attempt < 3 && image.rgba.empty(); ++attempt) frame(&image, withPanel);
    if (image.rgba.empty()) throw io::ObjError(path + ": no frame to save (the window has no area)");
    const std::vector<uint8_t> png = render::encodePng(image);
    io::writeReplacing(path, [&png](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
    });
}

}  // namespace quadtri::view
