// The bundled demo cage (data/mixed_limb.obj) and its surface tables, shared by the real-time
// loop's tests.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <quadtri/far/refiner.h>
#include "tools/obj_io.h"
#include "tools/realtime/surface_tables.h"

namespace quadtri::test {

struct DemoCage {
    io::ObjMesh mesh;
    std::unique_ptr<Refiner> refiner;  // refined to `level`
};
// data/mixed_limb.obj with its tags, refined to `level` under the default scheme.
DemoCage loadDemoCage(int level);

// Largest |a_i - b_i|; a and b of the same size.
float maxDifference(const std::vector<float>& a, const std::vector<float>& b);

}  // namespace quadtri::test
