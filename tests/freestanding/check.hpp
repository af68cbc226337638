// A registry of checks for the freestanding test: built with -fno-exceptions -fno-rtti and an
// operator new that traps. Each file registers its checks with a static `registration`; the
// registry is an intrusive list, so registering needs no heap either.
#ifndef POWERKEY_TESTS_FREESTANDING_CHECK_HPP
#define POWERKEY_TESTS_FREESTANDING_CHECK_HPP

namespace freestanding {

struct registration {
    const char* name;
    bool (*run)();
    registration* next;
    registration(const char* n, bool (*r)()) noexcept;
};

registration*& head() noexcept;

inline registration::registration(const char* n, bool (*r)()) noexcept
    : name(n), run(r), next(head()) {
    head() = this;
}

}  // namespace freestanding

#endif
