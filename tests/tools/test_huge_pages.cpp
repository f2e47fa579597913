// tools/memory/huge_pages.h: the tools' large blocks on huge pages. What a block holds must not
// change; where Linux has transparent huge pages, the advice must cover the block's first huge
// page too (the one its allocator's header shares), which the kernel shows per mapping as
// THPeligible in /proc/self/smaps.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "tools/memory/huge_pages.h"

namespace quadtri::test {
namespace {

using memory::adviseHugePages;
using memory::hugePageCapacity;

constexpr std::size_t kHuge = std::size_t(2) << 20;

TEST(HugePages, CapacityIsWholeHugePagesLessOnePage) {
    for (std::size_t bytes : {std::size_t(1), kHuge - 4096, kHuge - 4095, kHuge, 3 * kHuge + 17, std::size_t(1) << 30}) {
        const std::size_t capacity = hugePageCapacity(bytes);
        EXPECT_GE(capacity, bytes) << bytes;
        EXPECT_EQ((capacity + 4096) % kHuge, 0u) << bytes;
        EXPECT_LT(capacity - bytes, kHuge) << bytes;  // the least such capacity
    }
}

TEST(HugePages, AnAdvisedBlockHoldsWhatIsWritten) {
    for (std::size_t bytes : {std::size_t(100), std::size_t(3) << 20, (std::size_t(16) << 20) + 5}) {
        auto* block = static_cast<unsigned char*>(memory::allocateAdvised(bytes));
        ASSERT_NE(block, nullptr);
        for (std::size_t i = 0; i < bytes; ++i) block[i] = static_cast<unsigned char>(i * 7);
        for (std::size_t i = 0; i < bytes; ++i)
            if (block[i] != static_cast<unsigned char>(i * 7)) FAIL() << "byte " << i << " of " << bytes;
        std::free(block);
    }
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

TEST(HugePages, AdviceTakesInTheFirstHugePageAndKeepsItsBytes) {
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

#endif

}  // namespace
}  // namespace quadtri::test
