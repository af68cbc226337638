// powerkey detail: the speed macros, the only ones that change code rather than write it out:
// how much of a decoder the compiler inlines. The decoders are a dispatch (a front, a switch on
// the function code, one on an SDO value's kind) whose cases are small; inlined into their
// switch, the common cases need no frame and no registers saved, the rare ones are called out of
// line (docs/performance.md). Under -Os (firmware) one shared copy of each is smaller, so only
// POWERKEY_DETAIL_INLINE, the dispatch itself, stays forced there, and POWERKEY_DETAIL_SIZE is
// true: a function written twice for speed is written once, and a table kept only for speed
// (the address hash slots, the command byte table) gives way to a scan. Compilers other than g++
// and clang get no hints.
#ifndef POWERKEY_DETAIL_INLINE_HPP
#define POWERKEY_DETAIL_INLINE_HPP

// POWERKEY_DETAIL_INLINE_LAMBDA, after a lambda's parameter list: a handler a dispatch calls in
// place (canopen::visit_sdo_request), forced inline like the dispatch.
#if defined(__GNUC__)
#define POWERKEY_DETAIL_INLINE [[gnu::always_inline]]
#define POWERKEY_DETAIL_INLINE_LAMBDA __attribute__((always_inline))
#if defined(__OPTIMIZE_SIZE__)
#define POWERKEY_DETAIL_HOT
#define POWERKEY_DETAIL_COLD
#define POWERKEY_DETAIL_SIZE true
#else
#define POWERKEY_DETAIL_HOT [[gnu::always_inline]]
#define POWERKEY_DETAIL_COLD [[gnu::noinline]]
#define POWERKEY_DETAIL_SIZE false
#endif
#else
#define POWERKEY_DETAIL_INLINE
#define POWERKEY_DETAIL_INLINE_LAMBDA
#define POWERKEY_DETAIL_HOT
#define POWERKEY_DETAIL_COLD
#define POWERKEY_DETAIL_SIZE false
#endif

// POWERKEY_DETAIL_FLATTEN: an entry point whose model is a template argument (j1939::decode<M>)
// inlines the whole engine it calls, so that every read of the model's row is a constant and the
// paths the model never takes drop out, at every optimisation level (-Os included).
#if defined(__GNUC__)
#define POWERKEY_DETAIL_FLATTEN [[gnu::flatten]]
#else
#define POWERKEY_DETAIL_FLATTEN
#endif

// Tells g++ and clang that `condition` is false here (a row number a key matched is never the
// sentinel): the callers' tests of it drop out. Nothing elsewhere.
#if defined(__GNUC__)
#define POWERKEY_DETAIL_ASSUME_NOT(condition)   \
    do {                                        \
        if (condition) __builtin_unreachable(); \
    } while (false)
#else
#define POWERKEY_DETAIL_ASSUME_NOT(condition) \
    do {                                      \
    } while (false)
#endif

#endif  // POWERKEY_DETAIL_INLINE_HPP
