// The tools' memory policy, installed by linking this file (the CLI, the demo and the bench): the
// global operator new serves blocks of 2 MiB or more on huge pages (tools/memory/huge_pages.h),
// everything else from malloc as the default one does. The library's std::vector arrays, its
// level tables among them, come through here; the library itself sets no policy.
#include <cstdlib>
#include <new>

#include "tools/memory/huge_pages.h"

namespace {

void* allocate(std::size_t bytes) {
    if (bytes == 0) bytes = 1;
    for (;;) {
        if (void* data = quadtri::memory::allocateAdvised(bytes)) return data;
        std::new_handler handler = std::get_new_handler();
        if (!handler) throw std::bad_alloc();
        handler();
    }
}

}  // namespace

void* operator new(std::size_t bytes) { return allocate(bytes); }
void* operator new[](std::size_t bytes) { return allocate(bytes); }
void* operator new(std::size_t bytes, const std::nothrow_t&) noexcept {
    try {
        return allocate(bytes);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](std::size_t bytes, const std::nothrow_t& tag) noexcept { return operator new(bytes, tag); }
void operator delete(void* data) noexcept { std::free(data); }
void operator delete[](void* data) noexcept { std::free(data); }
void operator delete(void* data, std::size_t) noexcept { std::free(data); }
void operator delete[](void* data, std::size_t) noexcept { std::free(data); }
void operator delete(void* data, const std::nothrow_t&) noexcept { std::free(data); }
void operator delete[](void* data, const std::nothrow_t&) noexcept { std::free(data); }
