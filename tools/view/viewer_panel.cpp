// The viewer's panel (Dear ImGui): file, surface choices, display, selection and sharpness with
// the colour legend, timings, and the unsaved-edits prompt.
#include <imgui.h>

#include <cmath>
#include <cstdio>

#include "tools/render/surface_data.h"
#include "tools/view/viewer.h"

namespace quadtri::view {

namespace {

// A combo over `all`; true when the choice changed.
template <typename T>
bool combo(const char* label, T& value, const std::vector<T>& all) {
    bool changed = false;
    if (ImGui::BeginCombo(label, toString(value))) {
        for (const T& option : all)
            if (ImGui::Selectable(toString(option), option == value)) {
                changed = !(option == value);
                value = option;
            }
        ImGui::EndCombo();
    }
    return changed;
}

ImVec4 colorOf(glm::vec3 c) { return ImVec4(c.x, c.y, c.z, 1.0f); }

void legendEntry(const char* label, glm::vec3 color) {
    ImGui::ColorButton(label, colorOf(color), ImGuiColorEditFlags_NoTooltip, ImVec2(14, 14));
    ImGui::SameLine();
    ImGui::TextUnformatted(label);
}

}  // namespace

void Viewer::drawPanel() {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - kPanelWidth - kPanelMargin, kPanelMargin), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, io.DisplaySize.y - 2 * kPanelMargin), ImGuiCond_FirstUseEver);
    ImGui::Begin("quadtri");
    if (!message_.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", message_.c_str());
        ImGui::PopStyleColor();
        if (ImGui::SmallButton("Dismiss")) message_.clear();
    }
    drawFilePanel();
    drawSurfacePanel();
    drawDisplayPanel();
    drawSelectionPanel();
    drawTimings();
    ImGui::End();
    drawConfirmation();
    if (viewportCount() == 2) {  // which scheme each side shows
        for (int i = 0; i < 2; ++i) {
            const VkRect2D r = viewport(i);
            const Scheme scheme = i == 0 ? choices_.scheme : *choices_.compare;
            ImGui::GetBackgroundDrawList()->AddText(ImVec2(float(r.offset.x) + 12.0f, 10.0f),
                                                    IM_COL32(230, 230, 230, 255), toString(scheme));
        }
    }
}

void Viewer::drawFilePanel() {
    if (!ImGui::CollapsingHeader("File", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::Text("%s%s", document_.path().c_str(), document_.unsaved() ? " (edited)" : "");
    ImGui::InputText("##load", loadPath_.data(), loadPath_.size());
    ImGui::SameLine();
    if (ImGui::Button("Load")) requestLoad(loadPath_.data());
    ImGui::InputText("##save", savePath_.data(), savePath_.size());
    ImGui::SameLine();
    if (ImGui::Button("Save")) {
        try {
            document_.save(savePath_.data());
        } catch (const std::exception& e) {
            message_ = e.what();
        }
    }
    ImGui::InputText("##shot", shotPath_.data(), shotPath_.size());
    ImGui::SameLine();
    if (ImGui::Button("PNG")) pending_ = pending_ == Pending::None ? Pending::Screenshot : pending_;
    if (document_.mesh().hasUVs()) {
        ImGui::InputText("##texture", texturePath_.data(), texturePath_.size());
        ImGui::SameLine();
        if (ImGui::Button("Texture")) loadTexture(texturePath_.data());
    }
}

void Viewer::drawSurfacePanel() {
    if (!ImGui::CollapsingHeader("Surface", ImGuiTreeNodeFlags_DefaultOpen)) return;
    bool changed = combo("Scheme", choices_.scheme, allSchemes());
    changed |= ImGui::SliderInt("Level", &choices_.level, 0, 6);
    changed |= combo("Boundary", choices_.boundary, allBoundaries());
    changed |= combo("Creases", choices_.creaseMethod, allCreaseMethods());
    if (document_.mesh().hasUVs()) changed |= combo("UVs", choices_.uvs, allFVarLinearInterpolations());
    changed |= combo("Evaluator", choices_.evaluator, allEvaluators());
    changed |= combo("Tables", choices_.tables, allTableRoutes());
    changed |= ImGui::Checkbox("Adaptive tessellation", &choices_.adaptive);
    if (choices_.adaptive) ImGui::SliderFloat("Pixels per segment", &choices_.pixelsPerSegment, 2.0f, 64.0f, "%.0f");
    bool compare = choices_.compare.has_value();
    if (ImGui::Checkbox("Compare with", &compare)) {
        choices_.compare = compare ? std::optional<Scheme>(Scheme::CatmullClark) : std::nullopt;
        changed = true;
    }
    if (choices_.compare) {
        ImGui::SameLine();
        changed |= combo("##compare", *choices_.compare, allSchemes());
    }
    if (changed) needsRebuild_ = true;
    ImGui::Checkbox("Deform (two-bone skin)", &deform_);
    if (!surfaces_.empty() && !surfaces_[0]->skinProblem().empty()) ImGui::TextWrapped("%s", surfaces_[0]->skinProblem().c_str());
    ImGui::SliderFloat("Speed", &speed_, 0.05f, 3.0f);
    if (!deform_) needsUpdate_ = needsUpdate_ || changed;
}

void Viewer::drawDisplayPanel() {
    if (!ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (combo("Shading", view_.shading, allShadings())) needsUpdate_ = true;
    ImGui::Checkbox("Surface", &view_.showSurface);
    ImGui::SameLine();
    ImGui::Checkbox("Cage", &view_.showCage);
    ImGui::SameLine();
    ImGui::Checkbox("Points", &view_.showPoints);
    if (view_.shading == render::Shading::ReflectionLines) ImGui::SliderFloat("Stripes", &view_.stripes, 2.0f, 64.0f);
    ImGui::SliderFloat3("Light", &view_.light.direction.x, -1.0f, 1.0f);
    ImGui::ColorEdit3("Light colour", &view_.light.color.x);
    if (ImGui::Button("Frame the mesh (F)")) frameMesh();
    ImGui::TextDisabled("Drag: rotate (left), pan (right, middle); wheel: zoom");
    ImGui::TextDisabled("Click: select an edge or vertex; shift adds");
}

void Viewer::drawSelectionPanel() {
    if (!ImGui::CollapsingHeader("Sharpness", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const std::size_t edges = document_.selectedEdges().size(), vertices = document_.selectedVertices().size();
    ImGui::Text("Selected: %zu edge%s, %zu vert%s", edges, edges == 1 ? "" : "s", vertices, vertices == 1 ? "ex" : "ices");
    if (document_.hasSelection()) {
        float s = document_.selectionSharpness();
        bool infinite = s >= kInfiniteSharpness;
        bool changed = false;
        if (!infinite) changed |= ImGui::SliderFloat("Sharpness", &s, 0.0f, 9.99f, "%.2f");
        changed |= ImGui::Checkbox("Infinite", &infinite);
        if (changed) editSelection(infinite ? kInfiniteSharpness : std::min(s, 9.99f));
        if (ImGui::Button("Clear selection")) {
            document_.clearSelection();
            needsUpdate_ = true;
        }
    }
    ImGui::TextDisabled("Edge colours");
    legendEntry("0 smooth", render::sharpnessColor(0.0f));
    legendEntry("0+ semi-sharp", render::sharpnessColor(0.01f));
    legendEntry("5", render::sharpnessColor(5.0f));
    legendEntry("10- very sharp", render::sharpnessColor(9.99f));
    legendEntry("infinite, boundary", render::sharpnessColor(kInfiniteSharpness));
    legendEntry("selected", render::selectedColor());
}

void Viewer::drawTimings() {
    if (!ImGui::CollapsingHeader("Timings", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const bool ready = !surfaces_.empty() && surfaces_[0]->ready();
    if (ready && surfaces_[0]->adaptive()) {
        ImGui::Text("%s, adaptive tessellation:", toString(choices_.evaluator));
        ImGui::Text("%s", surfaces_[0]->adaptiveSummary().c_str());
    } else {
        ImGui::Text("%s, level %d: %d vertices", toString(choices_.evaluator), choices_.level,
                    ready ? surfaces_[0]->refiner().faces(choices_.level).numVertices() : 0);
        if (ready) ImGui::Text("%s tables", surfaces_[0]->routeDescription().c_str());
    }
    ImGui::Text("deform   %7.2f ms", times_.deformMs);
    ImGui::Text("evaluate %7.2f ms", times_.evaluateMs);
    ImGui::Text("normals  %7.2f ms", times_.normalsMs);
    ImGui::Text("draw     %7.2f ms", drawMs_);
    if (editMs_ >= 0.0) ImGui::Text("edit     %7.2f ms (the last sharpness change)", editMs_);
    ImGui::Text("%.1f fps", double(ImGui::GetIO().Framerate));
    ImGui::TextDisabled("Vulkan device: %s", gpu_->deviceName().c_str());
}

void Viewer::drawConfirmation() {
    if (pending_ == Pending::Screenshot) {
        pending_ = Pending::None;
        wantsScreenshot_ = true;
    }
    if (pending_ != Pending::Quit && pending_ != Pending::Load) return;
    ImGui::OpenPopup("Unsaved edits");
    if (!ImGui::BeginPopupModal("Unsaved edits", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::Text("%s has edits that are not saved.", document_.path().c_str());
    if (pending_ == Pending::Quit)
        ImGui::TextUnformatted("Quit anyway?");
    else
        ImGui::Text("Load %s anyway?", pendingPath_.c_str());
    const Pending action = pending_;
    bool done = false;
    if (ImGui::Button("Save, then continue")) {
        try {
            document_.save(savePath_.data());
            done = true;
        } catch (const std::exception& e) {
            message_ = e.what();
            pending_ = Pending::None;
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard the edits")) done = true;
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) pending_ = Pending::None;
    if (done) {
        pending_ = Pending::None;
        if (action == Pending::Quit)
            quit_ = true;
        else
            load(pendingPath_);
    }
    if (pending_ == Pending::None) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

}  // namespace quadtri::view
