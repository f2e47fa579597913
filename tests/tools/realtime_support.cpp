#include "tests/tools/realtime_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace quadtri::test {

DemoCage loadDemoCage(int level) {
    DemoCage cage{io::readObj(QUADTRI_DATA "/mixed_limb.obj"), nullptr};
    cage.refiner = std::make_unique<Refiner>(cage.mesh.descriptor(), cage.mesh.applyTags(Options()));
    cage.refiner->refineUniform(level);
    return cage;
}

float maxDifference(const std::vector<float>& a, const std::vector<float>& b) {
    EXPECT_EQ(a.size(), b.size());
    float largest = 0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) largest = std::max(largest, std::fabs(a[i] - b[i]));
    return largest;
}

}  // namespace quadtri::test
