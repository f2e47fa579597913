// The cage being edited: the loaded OBJ, the selection (edges as vertex pairs, vertices) and
// whether there are edits not yet saved (docs/viewer.md).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "tools/obj_io.h"

namespace quadtri::view {

class Document {
public:
    // Reads `path` (io::readObj's errors, "file:line: ..."; the current mesh is kept on failure).
    void load(const std::string& path);
    // Writes the cage with its tags to `path` (through a temporary file) and marks it saved.
    void save(const std::string& path);

    const io::ObjMesh& mesh() const { return mesh_; }
    const std::string& path() const { return path_; }
    bool loaded() const { return mesh_.numVertices() > 0; }
    bool unsaved() const { return unsaved_; }

    // Selection, 0-based vertices; `add` keeps what is selected (shift), else it is replaced.
    // Selecting what is already selected with `add` deselects it.
    void selectEdge(int a, int b, bool add);
    void selectVertex(int v, bool add);
    void clearSelection();
    const std::vector<std::pair<int, int>>& selectedEdges() const { return edges_; }
    const std::vector<int>& selectedVertices() const { return vertices_; }
    bool hasSelection() const { return !edges_.empty() || !vertices_.empty(); }
    // The sharpness the selection shows: the first selected edge's, else the first vertex's.
    float selectionSharpness() const;
    // Every selected edge's crease and vertex's corner sharpness (>= 10: infinite).
    void setSelectionSharpness(float sharpness);

private:
    io::ObjMesh mesh_;
    std::string path_;
    bool unsaved_ = false;
    std::vector<std::pair<int, int>> edges_;
    std::vector<int> vertices_;
};

}  // namespace quadtri::view
