// The freestanding test: every registered check runs with exceptions and RTTI off, and with an
// operator new that aborts, so any heap use anywhere in the library ends the test.
#include <cstdio>
#include <cstdlib>
#include <new>

#include "check.hpp"

void* operator new(std::size_t) { std::abort(); }
void* operator new[](std::size_t) { std::abort(); }
void operator delete(void*) noexcept { std::abort(); }
void operator delete[](void*) noexcept { std::abort(); }
void operator delete(void*, std::size_t) noexcept { std::abort(); }
void operator delete[](void*, std::size_t) noexcept { std::abort(); }

freestanding::registration*& freestanding::head() noexcept {
    static registration* h = nullptr;
    return h;
}

int main() {
    int failed = 0, count = 0;
    for (auto* r = freestanding::head(); r != nullptr; r = r->next, ++count) {
        if (!r->run()) {
            std::printf("FAILED: %s\n", r->name);
            ++failed;
        }
    }
    std::printf("%d checks, %d failed\n", count, failed);
    return failed == 0 && count > 0 ? 0 : 1;
}
