// Start-up code shared by the footprint firmwares: the core vector table (initial stack pointer
// and the 15 system exceptions of an ARMv6-M core, no device interrupts) and a reset handler that
// initialises .data and .bss as any real firmware does, then runs firmware_main().
#include <cstdint>

extern "C" {
extern std::uint32_t _estack, _sdata, _edata, _sidata, _sbss, _ebss;
[[noreturn]] void reset_handler();
}

[[noreturn]] void firmware_main();

namespace {
[[noreturn]] void trap() {
    for (;;) {
    }
}
using handler = void (*)();
}  // namespace

[[gnu::section(".vectors"), gnu::used]] extern const handler vector_table[16] = {
    reinterpret_cast<handler>(&_estack),
    reset_handler,
    trap,  // NMI
    trap,  // HardFault
    nullptr,
    nullptr,
    nullptr,
    nullptr,
    nullptr,
    nullptr,
    nullptr,
    trap,  // SVCall
    nullptr,
    nullptr,
    trap,  // PendSV
    trap,  // SysTick
};

// std::get and std::visit reach abort() on a valueless variant (bad_variant_access without
// exceptions); the library never makes one, but the call is linked in, as in any firmware.
extern "C" [[noreturn]] void abort() { trap(); }

extern "C" [[noreturn]] void reset_handler() {
    std::uint32_t* src = &_sidata;
    for (std::uint32_t* dst = &_sdata; dst < &_edata;) *dst++ = *src++;
    for (std::uint32_t* dst = &_sbss; dst < &_ebss;) *dst++ = 0;
    firmware_main();
}
