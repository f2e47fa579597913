// libFuzzer target: bytes as an OBJ file, read, refined to level 3 under every scheme with its UVs,
// checked by fuzz_oracles.h. A malformed file must be refused with io::ObjError, a bad mesh with TopologyError.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <sstream>
#include <string>

#include "tests/fuzz/fuzz_oracles.h"
#include "tools/obj_io.h"

namespace {

using namespace quadtri;

// Larger inputs add little but time: the interesting structure of a mesh fits in a few faces.
constexpr size_t kMaxInputBytes = 4096;
constexpr int kLevels = 3;
const char* const kFileName = "fuzz.obj";

// Every level's UV values are what its table makes, and every face corner names one of them.
void checkUVs(const Refiner& refiner) {
    for (int c = 0; c < refiner.numFVarChannels(); ++c)
        for (int L = 0; L <= refiner.maxLevel(); ++L) {
            const int n = refiner.numFVarValues(c, L);
            if (L > 0 && refiner.fvarLevelStencils(c, L).numStencils() != n) fuzz::fail("a UV table of the wrong size");
            for (int f = 0; f < refiner.faces(L).numFaces(); ++f)
                for (int value : refiner.fvarValuesOfFace(c, L, f))
                    if (value < 0 || value >= n) fuzz::fail("a face corner's UV index out of range");
        }
}

void refineUnder(const io::ObjMesh& mesh, Scheme scheme) {
    Options options = mesh.applyTags(Options());
    options.scheme = scheme;
    options.memoryBudgetBytes = fuzz::kFuzzBudgetBytes;
    std::unique_ptr<Refiner> refiner;
    FVarChannel uvs;
    try {
        refiner = std::make_unique<Refiner>(mesh.descriptor(uvs), options);
    } catch (const TopologyError& e) {
        fuzz::expectMessage(e);
        // The CLI names the file (and line) of a topology error.
        if (mesh.describe(e.diagnostic()).rfind(kFileName, 0) != 0) fuzz::fail("a topology error not located in the file");
        return;
    }
    try {
        refiner->refineUniform(kLevels);
    } catch (const MemoryBudgetError& e) {  // the levels built so far stay usable
        fuzz::expectMessage(e);
    }
    fuzz::checkRefinement(*refiner, mesh.positions);
    checkUVs(*refiner);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > kMaxInputBytes) return -1;  // not added to the corpus
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    io::ObjMesh mesh;
    try {
        mesh = io::parseObj(in, kFileName);
    } catch (const io::ObjError& e) {
        fuzz::expectMessage(e);
        if (std::string(e.what()).rfind(kFileName, 0) != 0) fuzz::fail("an OBJ error not naming the file");
        return 0;
    }
    for (Scheme scheme : allSchemes()) refineUnder(mesh, scheme);
    return 0;
}
