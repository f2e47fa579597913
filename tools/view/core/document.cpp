#include "tools/view/core/document.h"

#include <algorithm>

#include <quadtri/far/options.h>
#include "tools/view/core/cage_edits.h"

namespace quadtri::view {

void Document::load(const std::string& path) {
    io::ObjMesh mesh = io::readObj(path);
    if (mesh.numFaces() == 0) throw io::ObjError(path + ": no faces (f lines) to show");
    mesh_ = std::move(mesh);
    path_ = path;
    unsaved_ = false;
    clearSelection();
}

void Document::save(const std::string& path) {
    writeCage(path, mesh_);
    path_ = path;
    unsaved_ = false;
}

void Document::selectEdge(int a, int b, bool add) {
    if (a > b) std::swap(a, b);
    const auto found = std::find(edges_.begin(), edges_.end(), std::make_pair(a, b));
    if (!add) clearSelection();
    if (add && found != edges_.end())
        edges_.erase(found);
    else
        edges_.emplace_back(a, b);
}

void Document::selectVertex(int v, bool add) {
    const auto found = std::find(vertices_.begin(), vertices_.end(), v);
    if (!add) clearSelection();
    if (add && found != vertices_.end())
        vertices_.erase(found);
    else
        vertices_.push_back(v);
}

void Document::clearSelection() {
    edges_.clear();
    vertices_.clear();
}

float Document::selectionSharpness() const {
    if (!edges_.empty()) return creaseSharpness(mesh_, edges_[0].first, edges_[0].second);
    if (!vertices_.empty()) return cornerSharpness(mesh_, vertices_[0]);
    return 0.0f;
}

void Document::setSelectionSharpness(float sharpness) {
    sharpness = std::min(sharpness, kInfiniteSharpness);
    for (const auto& [a, b] : edges_) setCreaseSharpness(mesh_, a, b, sharpness);
    for (int v : vertices_) setCornerSharpness(mesh_, v, sharpness);
    unsaved_ = unsaved_ || hasSelection();
}

}  // namespace quadtri::view
