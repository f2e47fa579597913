// The scheme registry (far/schemes/schemes.cpp): every scheme has one name that reads back to it, a
// description, and rules; a value outside the registry is refused with a clear error.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "far/schemes/scheme.h"
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

TEST(Schemes, NamesReadBackToTheirScheme) {
    std::set<std::string> names;
    for (Scheme scheme : allSchemes()) {
        const std::string name = toString(scheme);
        EXPECT_TRUE(names.insert(name).second) << name << " is listed twice";
        EXPECT_EQ(schemeNamed(name), scheme) << name;
        EXPECT_EQ(name, rulesOf(scheme).name());
        EXPECT_FALSE(std::string(describe(scheme)).empty()) << name;
    }
    EXPECT_EQ(schemeNamed("catmark"), std::nullopt);
    EXPECT_EQ(schemeNamed(""), std::nullopt);
}

// The schemes the public enum names before any other are all registered, the default first.
TEST(Schemes, EveryEnumeratedSchemeIsRegistered) {
    const std::vector<Scheme>& all = allSchemes();
    ASSERT_FALSE(all.empty());
    EXPECT_EQ(all.front(), Options().scheme);
    for (Scheme scheme : {Scheme::Bilinear, Scheme::StamLoop, Scheme::SchaeferWarren, Scheme::CatmarkButterfly,
                          Scheme::CatmullClark, Scheme::Loop})
        EXPECT_NE(std::find(all.begin(), all.end(), scheme), all.end()) << toString(scheme);
    EXPECT_EQ(std::string(toString(Scheme::StamLoop)), "stam-loop");
    EXPECT_EQ(std::string(toString(Scheme::CatmarkButterfly)), "catmark-butterfly");
    EXPECT_EQ(std::string(toString(Scheme::CatmullClark)), "catmull-clark");
    EXPECT_EQ(std::string(toString(Scheme::Loop)), "loop");
}

TEST(Schemes, AnUnregisteredValueIsATopologyError) {
    const std::vector<int> sizes{3}, corners{0, 1, 2};
    const TopologyDescriptor triangle = descriptorOf(3, sizes, corners);
    Options options;
    options.scheme = Scheme(1000);
    try {
        Refiner refiner(triangle, options);
        FAIL() << "accepted";
    } catch (const TopologyError& e) {
        EXPECT_NE(std::string(e.what()).find("scheme 1000"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace quadtri::test
