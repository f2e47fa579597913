// quadtri-bench: quadtri against OpenSubdiv on generated tori: build time, table bytes and
// evaluation time per case, checked for agreement first, plus memcpy bandwidth for reference.
//   quadtri-bench [--quick] [--json FILE]
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/compare.h"
#include "bench/figures.h"
#include "bench/memcpy_bandwidth.h"
#include "bench/osd_case.h"
#include "bench/quadtri_case.h"
#include "bench/report.h"
#include "bench/torus.h"
#include "bench/vulkan_case.h"

namespace quadtri::bench {
namespace {

struct CaseSpec {
    int n;  // torus of n x n vertices
    TorusFaces faces;
    int level;
};

std::vector<CaseSpec> caseList(bool quick) {
    std::vector<CaseSpec> cases;
    const std::vector<std::pair<int, int>> sizes =
        quick ? std::vector<std::pair<int, int>>{{100, 3}} : std::vector<std::pair<int, int>>{{100, 4}, {320, 3}};
    for (auto [n, maxLevel] : sizes)
        for (TorusFaces faces : {TorusFaces::Quads, TorusFaces::Triangles})
            for (int level = 2; level <= maxLevel; ++level) cases.push_back({n, faces, level});
    for (int level = 2; level <= (quick ? 2 : 4); ++level) cases.push_back({100, TorusFaces::Mixed, level});
    return cases;
}

// Quads: Catmull-Clark on both sides; triangles: Loop on both; mixed: quadtri alone.
Scheme quadtriScheme(TorusFaces faces) { return faces == TorusFaces::Mixed ? Scheme::SchaeferWarren : Scheme::StamLoop; }
std::optional<OsdScheme> osdScheme(TorusFaces faces) {
    if (faces == TorusFaces::Quads) return OsdScheme::Catmark;
    if (faces == TorusFaces::Triangles) return OsdScheme::Loop;
    return std::nullopt;
}
std::string schemeName(TorusFaces faces) {
    const std::string qt = toString(quadtriScheme(faces));
    if (faces == TorusFaces::Quads) return qt + "/catmark";
    if (faces == TorusFaces::Triangles) return qt + "/loop";
    return qt;
}

CaseResult runCase(const ControlMesh& mesh, const CaseSpec& spec, int reps, VulkanContext* vulkan) {
    CaseResult result;
    result.mesh = mesh.name;
    result.scheme = schemeName(spec.faces);
    result.level = spec.level;

    QuadtriCase qt(mesh, quadtriScheme(spec.faces), spec.level);
    qt.prepare();
    result.refinedVertices = qt.refinedVertices();
    std::optional<OsdCase> osd;
    if (std::optional<OsdScheme> scheme = osdScheme(spec.faces)) {
        osd.emplace(mesh, *scheme, spec.level);
        osd->prepare();
        // Both libraries must produce the same last level before anything is timed.
        const double tolerance = 1e-5 * mesh.boundingBoxDiagonal();
        const MatchResult match = matchPositions(qt.lastLevel(), osd->lastLevel(), tolerance);
        if (!match.ok)
            throw std::runtime_error(mesh.name + " level " + std::to_string(spec.level) +
                                     ": quadtri and OpenSubdiv disagree on the last level (" + match.describe() +
                                     ", tolerance " + std::to_string(tolerance) + ")");
        std::cerr << "  agree with OpenSubdiv: " << match.describe() << "\n";
    }
    result.quadtri = qt.measure(reps);
    if (vulkan) {
        const VulkanFigures v = measureVulkan(*vulkan, qt.refiner(), mesh.positions, qt.lastLevel(),
                                              1e-5 * mesh.boundingBoxDiagonal(), reps);
        result.quadtri.evalVulkanMs = v.evalMs;
        result.quadtri.uploadVulkanMs = v.uploadMs;
    }
    if (osd) result.osd = osd->measure(reps);
    return result;
}

int usage(const char* message) {
    if (message) std::cerr << "quadtri-bench: " << message << "\n";
    std::cerr << "usage: quadtri-bench [--quick] [--json FILE] [--mesh NAME]\n"
                 "  --quick      CI-sized run: 100x100 tori at levels 2-3, mixed torus at level 2,\n"
                 "               3 repetitions, 32 MiB memcpy\n"
                 "  --json FILE  also write the figures as JSON to FILE\n"
                 "  --mesh NAME  only the cases of one mesh (torus100_quad, torus100_tri, torus320_quad,\n"
                 "               torus320_tri, torus100_mixed), e.g. to profile it\n";
    return message ? 2 : 0;
}

int run(int argc, char** argv) {
    bool quick = false;
    std::string jsonPath, onlyMesh;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--quick")) quick = true;
        else if (!std::strcmp(argv[i], "--json") && i + 1 < argc) jsonPath = argv[++i];
        else if (!std::strcmp(argv[i], "--mesh") && i + 1 < argc) onlyMesh = argv[++i];
        else if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) return usage(nullptr);
        else return usage((std::string("unknown argument ") + argv[i]).c_str());
    }
    const int reps = quick ? 3 : 5;

    BenchResult result;
    result.memcpyBytes = std::size_t(quick ? 32 : 256) << 20;
    std::cerr << "memcpy bandwidth (" << (result.memcpyBytes >> 20) << " MiB)...\n";
    result.memcpyGbps1 = memcpyGbps(result.memcpyBytes, 1, 5);
    result.memcpyGbps2 = memcpyGbps(result.memcpyBytes, 2, 5);

    std::unique_ptr<VulkanContext> vulkan;
    try {
        vulkan = std::make_unique<VulkanContext>();
        std::cerr << "Vulkan device: " << vulkan->deviceName() << "\n";
    } catch (const VulkanError& e) {
        std::cerr << "no Vulkan timings: " << e.what() << "\n";
    }

    std::map<std::pair<int, TorusFaces>, ControlMesh> meshes;
    std::vector<CaseSpec> cases = caseList(quick);
    if (!onlyMesh.empty()) {
        cases.erase(std::remove_if(cases.begin(), cases.end(),
                                   [&](const CaseSpec& c) { return torusName(c.n, c.faces) != onlyMesh; }),
                    cases.end());
        if (cases.empty()) return usage(("no case has the mesh " + onlyMesh).c_str());
    }
    for (size_t i = 0; i < cases.size(); ++i) {
        const CaseSpec& spec = cases[i];
        auto key = std::make_pair(spec.n, spec.faces);
        if (!meshes.count(key)) meshes.emplace(key, makeTorus(spec.n, spec.faces));
        const ControlMesh& mesh = meshes.at(key);
        std::cerr << "[" << i + 1 << "/" << cases.size() << "] " << mesh.name << " level " << spec.level << "\n";
        result.cases.push_back(runCase(mesh, spec, reps, vulkan.get()));
    }

    printMarkdown(std::cout, result);
    if (!jsonPath.empty()) writeJson(jsonPath, result);
    return 0;
}

}  // namespace
}  // namespace quadtri::bench

int main(int argc, char** argv) {
    try {
        return quadtri::bench::run(argc, argv);
    } catch (const std::exception& e) {
        std::cerr << "quadtri-bench: error: " << e.what() << "\n";
        return 1;
    }
}
