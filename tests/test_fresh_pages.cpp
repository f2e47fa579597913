// far/internal/fresh_pages.h: the arrays a level build fills, reserved onto huge pages and
// populated ahead. What they hold must not change; where Linux has transparent huge pages, the
// advice must cover the array's first huge page too (the one its allocator's header shares),
// which the kernel shows per mapping as THPeligible in /proc/self/smaps; populating makes the
// range's whole pages resident (mincore) and nothing around them, and leaves a reused block.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "far/internal/fresh_pages.h"

namespace quadtri::test {
namespace {

constexpr std::size_t kHuge = std::size_t(2) << 20;

TEST(FreshPages, CapacityIsWholeHugePagesLessOnePage) {
    for (std::size_t bytes : {std::size_t(1), kHuge - 4096, kHuge - 4095, kHuge, 3 * kHuge + 17, std::size_t(1) << 30}) {
        const std::size_t capacity = hugePageCapacity(bytes);
        EXPECT_GE(capacity, bytes) << bytes;
        EXPECT_EQ((capacity + 4096) % kHuge, 0u) << bytes;
        EXPECT_LT(capacity - bytes, kHuge) << bytes;  // the least such capacity
    }
}

TEST(FreshPages, KeepsWhatTheVectorHolds) {
    for (std::size_t n : {std::size_t(10), std::size_t(100000), std::size_t(3) << 20}) {
        std::vector<int> v(1000);
        std::iota(v.begin(), v.end(), 7);
        const std::vector<int> before = v;
        reserveFresh(v, n);
        EXPECT_GE(v.capacity(), n);
        EXPECT_EQ(v, before) << n;
        resizeFresh(v, n + 5);
        ASSERT_EQ(v.size(), n + 5);
        EXPECT_TRUE(std::equal(before.begin(), before.end(), v.begin()));
        EXPECT_TRUE(std::all_of(v.begin() + 1000, v.end(), [](int x) { return x == 0; }));
        assignFresh(v, n, 3);
        ASSERT_EQ(v.size(), n);
        EXPECT_TRUE(std::all_of(v.begin(), v.end(), [](int x) { return x == 3; }));
    }
    std::vector<int> big;
    reserveFresh(big, std::size_t(4) << 20);  // 16 MiB: rounded to whole huge pages
    EXPECT_EQ((big.capacity() * sizeof(int) + 4096) % kHuge, 0u);
}

#if defined(__linux__)

// Fresh anonymous memory of its own, unmapped at the end of the test.
class FreshMapping {
public:
    explicit FreshMapping(std::size_t bytes)
        : bytes_(bytes), data_(mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0)) {}
    ~FreshMapping() {
        if (data_ != MAP_FAILED) munmap(data_, bytes_);
    }
    FreshMapping(const FreshMapping&) = delete;
    FreshMapping& operator=(const FreshMapping&) = delete;
    bool ok() const { return data_ != MAP_FAILED; }
    unsigned char* bytes() const { return static_cast<unsigned char*>(data_); }

private:
    std::size_t bytes_;
    void* data_;
};

// The kernel's mode: "always", "madvise", "never", or "" where it has none.
std::string transparentHugePages() {
    std::ifstream f("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string line;
    std::getline(f, line);
    for (const char* mode : {"always", "madvise", "never"})
        if (line.find(std::string("[") + mode + "]") != std::string::npos) return mode;
    return "";
}

// THPeligible of the mapping that holds `address`, -1 if none says.
int hugePageEligible(const void* address) {
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    const auto a = std::uintptr_t(address);
    while (std::getline(smaps, line)) {
        std::uintptr_t begin = 0, end = 0;
        char dash = 0;
        std::istringstream head(line);
        if (head >> std::hex >> begin >> dash >> end && dash == '-') {
            inside = a >= begin && a < end;
        } else if (inside && line.rfind("THPeligible:", 0) == 0) {
            return std::stoi(line.substr(12));
        }
    }
    return -1;
}

TEST(FreshPages, AdviceTakesInTheFirstHugePageAndKeepsItsBytes) {
    const std::string mode = transparentHugePages();
    if (mode != "always" && mode != "madvise") GTEST_SKIP() << "no transparent huge pages";
    // Four huge pages on a huge-page boundary, from a mapping of five.
    const FreshMapping mapping(5 * kHuge);
    ASSERT_TRUE(mapping.ok());
    auto* base = reinterpret_cast<unsigned char*>((std::uintptr_t(mapping.bytes()) + kHuge - 1) / kHuge * kHuge);
    // An allocator's header in front of the array: the first page is touched before the advice.
    for (int i = 0; i < 16; ++i) base[i] = static_cast<unsigned char>(0xA0 + i);
    unsigned char* array = base + 16;
    const std::size_t bytes = 3 * kHuge + 12345;  // three huge pages and a small tail
    adviseHugePages(array, bytes);
    for (int i = 0; i < 16; ++i) EXPECT_EQ(base[i], 0xA0 + i);
    EXPECT_EQ(hugePageEligible(base), 1);  // the header's huge page
    EXPECT_EQ(hugePageEligible(base + 3 * kHuge - 1), 1);
    if (mode == "madvise") {  // the tail stays small, so that nothing past the array is resident
        EXPECT_EQ(hugePageEligible(base + 3 * kHuge), 0);
    }
    for (std::size_t i = 0; i < bytes; i += 4096) array[i] = 1;
    for (int i = 0; i < 16; ++i) EXPECT_EQ(base[i], 0xA0 + i);
}

// Whether the kernel takes MADV_POPULATE_WRITE (23; Linux 5.14), tried on a page of its own.
bool kernelPopulates() {
    const FreshMapping page(4096);
    return page.ok() && madvise(page.bytes(), 4096, 23) == 0;
}

// Which of the n pages from `first` are resident.
std::vector<bool> residentPages(const unsigned char* first, std::size_t n) {
    std::vector<unsigned char> bits(n);
    EXPECT_EQ(mincore(const_cast<unsigned char*>(first), n * 4096, bits.data()), 0);
    std::vector<bool> resident(n);
    for (std::size_t i = 0; i < n; ++i) resident[i] = bits[i] & 1;
    return resident;
}

// 64 fresh pages, where the kernel takes MADV_POPULATE_WRITE.
class PopulatePages : public ::testing::Test {
protected:
    static constexpr std::size_t kPages = 64;
    void SetUp() override {
        if (!kernelPopulates()) GTEST_SKIP() << "the kernel has no MADV_POPULATE_WRITE (Linux 5.14)";
        ASSERT_TRUE(mapping_.ok());
    }
    unsigned char* base() const { return mapping_.bytes(); }

private:
    FreshMapping mapping_{kPages * 4096};
};

TEST_F(PopulatePages, TheWholePagesOfAFreshRangeOnly) {
    // Bytes 100 into page 0 to 100 into page 40: whole pages 1-39.
    populatePages(base() + 100, 40 * 4096);
    const std::vector<bool> resident = residentPages(base(), kPages);
    EXPECT_FALSE(resident[0]);
    for (std::size_t i = 1; i < 40; ++i) EXPECT_TRUE(resident[i]) << i;
    for (std::size_t i = 40; i < kPages; ++i) EXPECT_FALSE(resident[i]) << i;
    for (std::size_t i = 0; i < kPages * 4096; ++i)
        if (base()[i] != 0) FAIL() << "byte " << i << " changed";
}

TEST_F(PopulatePages, LeavesARangeWhoseLastPageIsResident) {
    base()[39 * 4096] = 7;  // a block the allocator reused: taken as resident throughout
    populatePages(base(), 40 * 4096);
    const std::vector<bool> resident = residentPages(base(), kPages);
    for (std::size_t i = 0; i < 39; ++i) EXPECT_FALSE(resident[i]) << i;
    EXPECT_EQ(base()[39 * 4096], 7);
}

#endif

}  // namespace
}  // namespace quadtri::test
