// libFuzzer target: bytes as an OBJ file, read, refined to level 3 under every scheme, checked by
// fuzz_oracles.h. A malformed file must be refused with io::ObjError, a bad mesh with TopologyError.
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

void refineUnder(const io::ObjMesh& mesh, Scheme scheme) {
    Options options = mesh.applyTags(Options());
    options.scheme = scheme;
    options.memoryBudgetBytes = fuzz::kFuzzBudgetBytes;
    std::unique_ptr<Refiner> refiner;
    try {
        refiner = std::make_unique<Refiner>(mesh.descriptor(), options);
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
