// libFuzzer target: bytes decoded into a TopologyDescriptor (face sizes 0-8, vertex, face and
// sharpness values in and out of range, negative counts, null arrays) and the options, refined
// to level 1-3, checked by fuzz_oracles.h. Invalid input must be refused with TopologyError.
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "tests/fuzz/fuzz_oracles.h"

namespace {

using namespace quadtri;

// The input read front to back; past its end every byte reads 0.
class ByteReader {
public:
    ByteReader(const uint8_t* data, size_t size) : data_(data), size_(size) {}
    unsigned next() { return size_ ? (--size_, *data_++) : 0u; }

private:
    const uint8_t* data_;
    size_t size_;
};

// Mostly an index in [0, count), sometimes just past the end, negative or extreme.
int decodeIndex(ByteReader& in, int count) {
    unsigned b = in.next();
    if (b < 0xF0) return count > 0 ? int(b % unsigned(count)) : 0;
    if (b < 0xF8) return count + int(b - 0xF0);
    if (b < 0xFE) return -1 - int(b - 0xF8);
    return b == 0xFE ? INT_MAX : INT_MIN;
}

// Mostly a sharpness in [0, 15), sometimes a value the validator must refuse or clamp.
float decodeSharpness(ByteReader& in) {
    constexpr float inf = std::numeric_limits<float>::infinity();
    const float special[16] = {std::numeric_limits<float>::quiet_NaN(), inf, -inf, -1.0f, -0.0f,
                               std::numeric_limits<float>::max(), std::numeric_limits<float>::denorm_min(), 10.0f,
                               9.999f, 1e-30f, 0.001f, 0.5f, 1.0f, 2.0f, 10.5f, 100.0f};
    unsigned b = in.next();
    return b >= 0xF0 ? special[b - 0xF0] : float(b) / 16.0f;
}

// What one input asks for: the descriptor's arrays, options, level and the control positions' seed.
struct FuzzedMesh {
    std::vector<int> faceSizes, faceVerts, creasePairs, corners, holes;
    std::vector<float> creaseSharpness, cornerSharpness;
    TopologyDescriptor desc;
    Options options;
    int levels = 1;
    std::vector<float> positions;
};

// One of the descriptor's documented misuses, or none (most inputs).
enum class Misuse { None, NegativeVertices, NegativeFaces, NegativeCreases, NegativeCorners, NegativeHoles,
                    NullFaceVerts, NullCreaseWeights, NullHoles };

// Finite positions in [-scale, scale) from a seed, scale a power of two from subnormal to near FLT_MAX.
std::vector<float> decodePositions(ByteReader& in, int numVertices) {
    uint64_t state = in.next() * 0x9E3779B97F4A7C15ull + 1;
    float scale = std::ldexp(1.0f, int(in.next()) - 128);
    std::vector<float> xyz(3 * size_t(std::max(numVertices, 0)));
    for (float& x : xyz) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        x = scale * (float(state >> 40) / float(1 << 23) - 1.0f);
    }
    return xyz;
}

void decode(ByteReader& in, FuzzedMesh& m) {
    unsigned choice = in.next();
    // The top quarter of the byte picks the schemes added after the corpus was made, so that the
    // checked-in inputs below it keep their scheme.
    m.options.scheme = choice < 192 ? Scheme(choice % 4) : choice % 2 ? Scheme::CatmullClark : Scheme::Loop;
    m.options.smoothTriangles = m.options.scheme == Scheme::CatmullClark && choice / 2 % 2;
    m.options.boundary = BoundaryInterpolation(choice / 4 % 3);
    m.options.creaseMethod = CreaseMethod(choice / 12 % 2);
    m.options.leftHanded = choice / 24 % 2;
    m.options.memoryBudgetBytes = fuzz::kFuzzBudgetBytes;
    m.levels = 1 + int(in.next() % 3);
    unsigned misuse = in.next();
    Misuse defect = misuse >= 0xF8 ? Misuse(misuse - 0xF8 + 1) : Misuse::None;

    const int numVertices = int(in.next() % 48);
    const int numFaces = int(in.next() % 24);
    for (int f = 0; f < numFaces; ++f) {
        int size = int(in.next() % 9);
        m.faceSizes.push_back(size);
        for (int k = 0; k < size; ++k) m.faceVerts.push_back(decodeIndex(in, numVertices));
    }
    const int numCreases = int(in.next() % 8);
    for (int c = 0; c < numCreases; ++c) {
        m.creasePairs.push_back(decodeIndex(in, numVertices));
        m.creasePairs.push_back(decodeIndex(in, numVertices));
        m.creaseSharpness.push_back(decodeSharpness(in));
    }
    const int numCorners = int(in.next() % 8);
    for (int c = 0; c < numCorners; ++c) {
        m.corners.push_back(decodeIndex(in, numVertices));
        m.cornerSharpness.push_back(decodeSharpness(in));
    }
    const int numHoles = int(in.next() % 4);
    for (int h = 0; h < numHoles; ++h) m.holes.push_back(decodeIndex(in, numFaces));
    m.positions = decodePositions(in, numVertices);

    TopologyDescriptor& d = m.desc;
    d.numVertices = defect == Misuse::NegativeVertices ? -1 : numVertices;
    d.numFaces = defect == Misuse::NegativeFaces ? -numFaces - 1 : numFaces;
    d.numVertsPerFace = m.faceSizes.data();
    d.faceVertIndices = defect == Misuse::NullFaceVerts ? nullptr : m.faceVerts.data();
    d.numCreases = defect == Misuse::NegativeCreases ? -numCreases - 1 : numCreases;
    d.creaseVertexPairs = m.creasePairs.data();
    d.creaseWeights = defect == Misuse::NullCreaseWeights ? nullptr : m.creaseSharpness.data();
    d.numCorners = defect == Misuse::NegativeCorners ? -numCorners - 1 : numCorners;
    d.cornerVertexIndices = m.corners.data();
    d.cornerWeights = m.cornerSharpness.data();
    d.numHoles = defect == Misuse::NegativeHoles ? -numHoles - 1 : numHoles;
    d.holeIndices = defect == Misuse::NullHoles ? nullptr : m.holes.data();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    ByteReader in(data, size);
    FuzzedMesh m;
    decode(in, m);
    std::unique_ptr<Refiner> refiner;
    try {
        refiner = std::make_unique<Refiner>(m.desc, m.options);
    } catch (const TopologyError& e) {
        fuzz::expectMessage(e);
        return 0;
    }
    try {
        refiner->refineUniform(m.levels);
    } catch (const MemoryBudgetError& e) {  // the levels built so far stay usable
        fuzz::expectMessage(e);
    }
    fuzz::checkRefinement(*refiner, m.positions);
    return 0;
}
