// The operations that the benchmark (bench.cpp) times and the instruction counter (icount.cpp)
// counts, defined once so that both measure exactly the same code on exactly the same inputs.
//
// An operation runs `calls` calls of one library function, cycling through a fixed set of inputs
// (frames or messages taken from the manuals). Two barriers keep the optimiser honest:
//   opaque(x)  the compiler forgets what x is, so inputs cannot be folded at compile time;
//   keep(r)    the compiler must produce every byte of r in memory, so no work can be dropped.
// The floor operation reads each frame (identifier, format, dlc and the eight data bytes) and
// nothing else: the least any decoder must do. Every result is also reported relative to it.
#ifndef POWERKEY_BENCH_OPS_HPP
#define POWERKEY_BENCH_OPS_HPP

#include <powerkey/powerkey.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace bench {

template <class T>
inline void keep(const T& v) noexcept {
    asm volatile("" : : "m"(v) : "memory");
}

template <class T>
inline T opaque(T v) noexcept {
    asm volatile("" : "+m"(v));
    return v;
}

// One measured operation. `calls` is the number of library calls; `per_call` says what one call
// is when it is more than one frame (the segmented reader), for the tables.
struct op {
    std::string_view name;
    void (*run)(std::size_t calls);
    std::string_view per_call = "frame";
};

// Marks an operation's lambda: its library call is inlined into the loop of `cycle`, as the floor
// reads its frame inline, whichever other operations share the lambda's type (the decode_all<N>
// of two operations with N inputs each share one closure, which g++ otherwise calls out of line:
// +13..16 instructions per call on those rows only, CHANGELOG.md "How we got here").
#define BENCH_INLINE __attribute__((always_inline))

// Runs fn on inputs[0], inputs[1], ... (wrapping) `calls` times, keeping every result.
template <class In, std::size_t N, class Fn>
[[gnu::always_inline]] inline void cycle(const std::array<In, N>& inputs, std::size_t calls,
                                         Fn fn) noexcept {
    const In* in = opaque(inputs.data());
    std::size_t j = 0;
    for (std::size_t i = 0; i < calls; ++i) {
        keep(fn(in[j]));
        j = j + 1 == N ? 0 : j + 1;
    }
}

using powerkey::can::candump;
namespace co = powerkey::canopen;
namespace pc = powerkey::can;

inline constexpr co::node_id node = 0x15;

// classify() was rewritten from a scan of the function bases to a switch for speed (issue 7);
// this proves the two agree on all 2048 standard identifiers.
constexpr bool classify_matches_scan() {
    for (std::uint16_t v = 0; v <= 0x7FF; ++v) {
        co::cob_info expected{co::function::other, 0};
        if (v == 0x000) expected = {co::function::nmt, 0};
        if (v == 0x080) expected = {co::function::sync, 0};
        const auto n = static_cast<std::uint8_t>(v & 0x7F);
        for (co::function f : powerkey::enum_values<co::function>())
            if (n != 0 && co::detail::per_node_base(f) != 0 &&
                co::detail::per_node_base(f) + n == v)
                expected = {f, n};
        if (co::classify(pc::standard_id::make(v).value()) != expected) return false;
    }
    return true;
}
static_assert(classify_matches_scan());

// --- inputs: frames and messages exactly as the manuals print them ---------------------------

inline constexpr std::array core_frames = {
    candump("000#0115"),
    candump("080#"),
    candump("715#7F"),
    candump("715#05"),
    candump("615#4000200100000000"),
    candump("595#4B17100064000000"),
    candump("615#2B17100064000000"),
    candump("595#6017100000000000"),
};

inline constexpr std::array nmt_frames = {
    candump("000#0115"), candump("000#0215"), candump("000#8015"),
    candump("000#8115"), candump("000#8215"), candump("000#0100"),
};
inline constexpr std::array nmt_messages = {
    co::nmt_message{co::nmt_command::start, 0x15},
    co::nmt_message{co::nmt_command::stop, 0x15},
    co::nmt_message{co::nmt_command::enter_pre_operational, 0x15},
    co::nmt_message{co::nmt_command::reset_node, 0x15},
};

inline constexpr std::array heartbeat_frames = {candump("715#00"), candump("715#7F"),
                                                candump("715#05"), candump("715#04")};
inline constexpr std::array heartbeat_messages = {
    co::heartbeat_message{co::nmt_state::boot_up},
    co::heartbeat_message{co::nmt_state::operational},
    co::heartbeat_message{co::nmt_state::pre_operational},
    co::heartbeat_message{co::nmt_state::stopped}};

// Expedited SDO requests (client -> keypad) and responses (keypad -> client).
inline constexpr std::array sdo_request_frames = {
    candump("615#4000200100000000"),
    candump("615#2B17100064000000"),
    candump("615#2F03200520000000"),
    candump("615#4017100000000000"),
};
inline constexpr std::array sdo_response_frames = {
    candump("595#4B17100064000000"),
    candump("595#6017100000000000"),
    candump("595#4F00200101000000"),
    candump("595#6003200500000000"),
};
inline constexpr std::array sdo_download_messages = {
    co::sdo_download_request{{0x1017, 0}, co::expedited_data::u16(100)},
    co::sdo_download_request{{0x2003, 5}, co::expedited_data::u8(0x20)},
    co::sdo_download_request{{0x1800, 5}, co::expedited_data::u16(50)},
    co::sdo_download_request{{0x2013, 0}, co::expedited_data::u8(0x16)},
};
inline constexpr std::array sdo_upload_response_messages = {
    co::sdo_upload_response{{0x1017, 0}, co::expedited_data::u16(100)},
    co::sdo_upload_response{{0x2000, 1}, co::expedited_data::u8(0x01)},
    co::sdo_upload_response{{0x1018, 1}, co::expedited_data::u32(0x0000'0363)},
    co::sdo_upload_response{{0x2003, 5}, co::expedited_data::u8(0x3F)},
};

inline constexpr std::array candump_texts = {
    std::string_view("000#0115"),
    std::string_view("715#7F"),
    std::string_view("195#0100000017"),
    std::string_view("215#0102040880402010"),
    std::string_view("615#4000200100000000"),
    std::string_view("18EF2100#041B8000FFFFFFFF"),
};
inline constexpr std::array candump_frames = {
    candump("000#0115"),
    candump("715#7F"),
    candump("195#0100000017"),
    candump("215#0102040880402010"),
    candump("615#4000200100000000"),
    candump("18EF2100#041B8000FFFFFFFF"),
};

// A segmented upload of the device name, object 1008h ("BlinkMarine", 11 bytes, 3 replies).
struct upload_case {
    co::sdo_address address;
    std::array<pc::frame, 3> replies;
};
inline constexpr std::array upload_cases = {
    upload_case{{0x1008, 0},
                {candump("595#410810000B000000"), candump("595#00426C696E6B4D61"),
                 candump("595#1772696E65000000")}}};

namespace detail {
// True when every input decodes: no benchmark may silently measure an error path.
template <class Frames, class Decode>
constexpr bool all_decode(const Frames& frames, Decode d) {
    for (const auto& f : frames)
        if (!d(f).has_value()) return false;
    return true;
}
}  // namespace detail

// How many frames of `log` a keypad of model m at node 15h decodes (the others: other nodes' or
// other devices' frames).
template <std::size_t N>
constexpr std::size_t keypad_frames(const std::array<pc::frame, N>& log, powerkey::model m) {
    std::size_t n = 0;
    for (const auto& f : log)
        if (powerkey::decode(f, node, m).has_value()) ++n;
    return n;
}
// Those frames decoded, in order (K: their number): what the encoders are given.
template <std::size_t K, std::size_t N>
constexpr auto keypad_messages(const std::array<pc::frame, N>& log, powerkey::model m) {
    std::array<powerkey::message, K> out{};
    std::size_t n = 0;
    for (const auto& f : log)
        if (const auto r = powerkey::decode(f, node, m)) out[n++] = *r;
    return out;
}

// The one codec as model m at node 15h: every frame decoded, or every message (any message
// type) encoded.
template <std::size_t N>
[[gnu::always_inline]] inline void decode_all(const std::array<pc::frame, N>& frames,
                                              powerkey::model model, std::size_t calls) {
    const auto n = opaque(node);
    const auto m = opaque(model);
    cycle(frames, calls,
          [n, m](const pc::frame& f) BENCH_INLINE { return powerkey::decode(f, n, m); });
}
template <class T, std::size_t N>
[[gnu::always_inline]] inline void encode_all(const std::array<T, N>& messages,
                                              powerkey::model model, std::size_t calls) {
    const auto n = opaque(node);
    const auto m = opaque(model);
    cycle(messages, calls,
          [n, m](const T& msg) BENCH_INLINE { return powerkey::encode(n, m, msg); });
}
// The same with the model a template argument: encode<M>(node, msg).
template <powerkey::model M, class T, std::size_t N>
[[gnu::always_inline]] inline void encode_all(const std::array<T, N>& messages, std::size_t calls) {
    const auto n = opaque(node);
    cycle(messages, calls, [n](const T& msg) BENCH_INLINE { return powerkey::encode<M>(n, msg); });
}

// --- the operations -------------------------------------------------------------------------

inline void floor_read(std::size_t calls) {
    cycle(core_frames, calls, [](const pc::frame& f) {
        const auto& b = f.bytes();
        return f.raw_id() ^ (f.is_extended() ? 0x8000'0000u : 0u) ^ f.size() ^
               static_cast<std::uint32_t>(powerkey::detail::load_le<4>(b, 0)) ^
               static_cast<std::uint32_t>(powerkey::detail::load_le<4>(b, 4));
    });
}

inline void candump_parse(std::size_t calls) {
    cycle(candump_texts, calls, [](std::string_view t) { return pc::parse_candump(t); });
}
inline void candump_format(std::size_t calls) {
    cycle(candump_frames, calls, [](const pc::frame& f) { return pc::format_candump(f); });
}
inline void nmt_decode(std::size_t calls) {
    cycle(nmt_frames, calls, [](const pc::frame& f) { return co::decode_nmt(f); });
}
inline void nmt_encode(std::size_t calls) {
    cycle(nmt_messages, calls, [](const co::nmt_message& m) { return co::encode(m); });
}
inline void heartbeat_decode(std::size_t calls) {
    const auto n = opaque(node);
    cycle(heartbeat_frames, calls, [n](const pc::frame& f) { return co::decode_heartbeat(f, n); });
}
inline void heartbeat_encode(std::size_t calls) {
    const auto n = opaque(node);
    cycle(heartbeat_messages, calls,
          [n](const co::heartbeat_message& m) { return co::encode(n, m); });
}
inline void sdo_request_decode(std::size_t calls) {
    const auto n = opaque(node);
    cycle(sdo_request_frames, calls,
          [n](const pc::frame& f) { return co::decode_sdo_request(f, n); });
}
inline void sdo_response_decode(std::size_t calls) {
    const auto n = opaque(node);
    cycle(sdo_response_frames, calls,
          [n](const pc::frame& f) { return co::decode_sdo_response(f, n); });
}
inline void sdo_download_encode(std::size_t calls) {
    const auto n = opaque(node);
    cycle(sdo_download_messages, calls,
          [n](const co::sdo_download_request& m) { return co::encode(n, m); });
}
inline void sdo_upload_response_encode(std::size_t calls) {
    const auto n = opaque(node);
    cycle(sdo_upload_response_messages, calls,
          [n](const co::sdo_upload_response& m) { return co::encode(n, m); });
}
inline void segmented_upload_read(std::size_t calls) {
    const auto n = opaque(node);
    cycle(upload_cases, calls, [n](const upload_case& c) {
        co::segmented_upload<32> reader(n);
        keep(reader.start(c.address));
        for (const auto& reply : c.replies) keep(reader.step(reply));
        return reader.text().size();
    });
}

inline constexpr op core_ops[] = {
    {"floor/read_frame", floor_read},
    {"candump/parse", candump_parse},
    {"candump/format", candump_format},
    {"nmt/decode", nmt_decode},
    {"nmt/encode", nmt_encode},
    {"heartbeat/decode", heartbeat_decode},
    {"heartbeat/encode", heartbeat_encode},
    {"sdo_expedited/decode_request", sdo_request_decode},
    {"sdo_expedited/decode_response", sdo_response_decode},
    {"sdo_expedited/encode_download", sdo_download_encode},
    {"sdo_expedited/encode_upload_response", sdo_upload_response_encode},
    {"sdo_segmented/read_11_bytes", segmented_upload_read, "transfer (4 frames)"},
};

}  // namespace bench

#endif  // POWERKEY_BENCH_OPS_HPP
