// One limit case on quadtri's side: per-frame limit positions and unit normals of the last level's
// vertices, by the factorized LimitStencilTable (control vertices straight to the limit) and by
// the per-level tables followed by the limit table over the last level, serial and threaded; and
// the cheaper MeshNormals of the last level.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "bench/figures.h"
#include "bench/meshes/torus.h"
#include <quadtri/far/limit_stencil_table.h>
#include <quadtri/far/mesh_normal_table.h>
#include <quadtri/far/options.h>
#include <quadtri/far/refiner.h>

namespace quadtri {
inline namespace v0 {
class VulkanContext;
}  // namespace v0
}  // namespace quadtri

namespace quadtri::bench {

class LimitCase {
public:
    LimitCase(const ControlMesh& mesh, Scheme scheme, int level);
    ~LimitCase();

    // Builds the refiner and tables, evaluates every way once and checks that they agree
    // (threaded = serial bitwise; per-level chain and factorized within 1e-5 of the diagonal).
    void prepare();

    const std::vector<float>& positions() const { return position_; }  // factorized (else the chain), serial
    const std::vector<float>& normals() const { return normal_; }
    int numPoints() const { return limitOverLevel_.numStencils(); }
    // Why the factorized table is not there (the memory budget refused it), or empty.
    const std::string& factorizedRefused() const { return factorizedRefused_; }

    // vulkan: when given, also the factorized limit on that device.
    LimitFigures measure(int reps, VulkanContext* vulkan);

private:
    void limitFactorized(bool threaded, std::vector<float>& position, std::vector<float>& normal);
    void levelsThenLimit(bool threaded, std::vector<float>& position, std::vector<float>& normal);
    void meshNormals(bool threaded, std::vector<float>& normal);

    const ControlMesh& mesh_;
    Options options_;
    int level_;
    std::unique_ptr<Refiner> refiner_;
    LimitStencilTable limit_, limitOverLevel_;
    MeshNormalTable meshTable_;
    std::vector<std::vector<float>> levels_;  // per level, for the chain (level 0: the control positions)
    std::vector<float> position_, normal_;
    std::string factorizedRefused_;
    MemoryFigures memory_;  // the refiner, every table and the buffers, after prepare()
};

}  // namespace quadtri::bench
