// powerkey: finding a dictionary row, by address (the decoders) and by object (the encoders, the
// virtual keypad, the tool), through compact rows and hash tables made at compile time
// (docs/models.md, "The object dictionaries"). For a model known when the program is built, the
// same tables of its one dictionary (one_dictionary, chosen by the type of its layout).
#ifndef POWERKEY_KEYPAD_LOOKUP_HPP
#define POWERKEY_KEYPAD_LOOKUP_HPP

#include <powerkey/canopen/sdo.hpp>
#include <powerkey/detail/inline.hpp>
#include <powerkey/detail/lookup.hpp>
#include <powerkey/keypad/dictionaries.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/keypad/objects.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace powerkey {

namespace detail {
// An SDO address as the frame carries it in bytes 1..3: index | sub-index << 16.
constexpr std::uint32_t wire_key(canopen::sdo_address a) noexcept {
    return a.index | (std::uint32_t{a.subindex} << 16);
}

// The values a number kind accepts: min..min + span, or `also` (a row's min, max - min, also).
struct value_range {
    std::uint32_t min = 0;
    std::uint32_t span = 0xFFFF'FFFF;
    std::uint32_t also = 0xFFFF'FFFF;
    [[nodiscard]] constexpr bool contains(std::uint32_t v) const noexcept {
        return v - min <= span || v == also;
    }
    friend constexpr bool operator==(const value_range&, const value_range&) noexcept = default;
};

struct codec_row {
    std::uint32_t key;  // the wire_key of the address
    object id;
    value_kind kind;
    // Bits 0..2 the size (object_row::size), bit 3 readable, bit 4 writable, bits 5..7 a
    // led_part's width in bits / 4.
    std::uint8_t flags;
    std::uint8_t a;  // the range (value_ranges); led_plane: the plane; led_part: its first bit

    [[nodiscard]] constexpr canopen::sdo_address address() const noexcept {
        return {static_cast<std::uint16_t>(key), static_cast<std::uint8_t>(key >> 16)};
    }
    [[nodiscard]] constexpr std::uint8_t size() const noexcept { return flags & 7; }
    [[nodiscard]] constexpr bool readable() const noexcept { return (flags & 8) != 0; }
    [[nodiscard]] constexpr bool writable() const noexcept { return (flags & 16) != 0; }
    [[nodiscard]] constexpr unsigned part_width() const noexcept { return (flags >> 5) * 4u; }
    [[nodiscard]] constexpr std::uint64_t packed() const noexcept {
        return key | std::uint64_t{static_cast<std::uint8_t>(id)} << 24 |
               std::uint64_t{static_cast<std::uint8_t>(kind)} << 32 | std::uint64_t{flags} << 40 |
               std::uint64_t{a} << 48;
    }
};

constexpr value_range range_of(const object_row& r) noexcept {
    return {r.min, r.max - r.min, r.also};
}

// Calls f(row) for every row of every dictionary.
template <class F>
constexpr void for_each_row(F f) noexcept {
    for (const auto rows : dictionary_rows)
        for (const auto& r : rows) f(r);
}

constexpr auto collect_ranges() noexcept {
    distinct_set<value_range, 64> s;
    for_each_row([&s](const object_row& r) { s.add(range_of(r)); });
    return s;
}
inline constexpr auto all_ranges = collect_ranges();
inline constexpr auto value_ranges = [] {
    std::array<value_range, all_ranges.size> t{};
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = all_ranges.items[i];
    return t;
}();

constexpr codec_row codec_row_of(const object_row& r) noexcept {
    const object_info k = object_infos[static_cast<std::size_t>(r.id)];
    codec_row c{
        wire_key(r.address), r.id, k.kind,
        static_cast<std::uint8_t>(r.size | (r.readable() ? 8 : 0) | (r.writable() ? 16 : 0)), 0};
    if (k.kind == value_kind::led_plane) {
        c.a = static_cast<std::uint8_t>(k.holds);
    } else if (k.kind == value_kind::led_part) {
        c.a = k.offset;
        c.flags = static_cast<std::uint8_t>(c.flags | (k.width / 4) << 5);
    } else {
        for (std::size_t i = 0; i < value_ranges.size(); ++i)
            if (value_ranges[i] == range_of(r)) c.a = static_cast<std::uint8_t>(i);
    }
    return c;
}
// A led_part's width fits the row: a multiple of 4 bits, at most 28.
constexpr bool part_widths_fit() noexcept {
    for (const auto& k : object_infos)
        if (k.kind == value_kind::led_part && (k.width % 4 != 0 || k.width / 4 > 7)) return false;
    return true;
}
static_assert(part_widths_fit());

// The distinct codec rows, packed (a 64-bit compare each: clang counts constexpr steps); at most
// 254, so that a row number (1..) and the sentinel fit a byte.
using codec_row_set = distinct_set<std::uint64_t, 254>;
constexpr codec_row_set collect_codec_rows() noexcept {
    codec_row_set s;
    for_each_row([&s](const object_row& r) { s.add(codec_row_of(r).packed()); });
    return s;
}
inline constexpr codec_row_set all_codec_rows = collect_codec_rows();
// The codec rows, numbered from 1: row 0 is a sentinel whose key no address has (a wire key is 24
// bits), so that an empty hash slot (0) fails the lookup's key test like a wrong row, with no test
// of its own.
inline constexpr codec_row no_codec_row{0xFFFF'FFFF, object{}, value_kind::none, 0, 0};
inline constexpr auto codec_rows = [] {
    std::array<codec_row, all_codec_rows.size + 1> t{};
    t[0] = no_codec_row;
    for (std::size_t i = 0; i < all_codec_rows.size; ++i) {
        const auto v = all_codec_rows.items[i];
        t[i + 1] = {static_cast<std::uint32_t>(v) & 0xFF'FFFF, static_cast<object>(v >> 24),
                    static_cast<value_kind>(v >> 32), static_cast<std::uint8_t>(v >> 40),
                    static_cast<std::uint8_t>(v >> 48)};
    }
    return t;
}();
// The codec row number (1..) of a full row.
constexpr std::uint8_t codec_row_number(const object_row& r) noexcept {
    return static_cast<std::uint8_t>(all_codec_rows.find(codec_row_of(r).packed()) + 1);
}

// Per dictionary, a hash table of codec row numbers (0: empty) by address: open addressing
// over 256 slots, with one multiplier for all five dictionaries, the first candidate with which
// every address is found within two probes. All five tables in one array, dictionary d's at
// d * 256: a fixed size costs some slots (a dictionary has 44..101 rows) and saves the lookup
// reading a size and a place per dictionary.
inline constexpr unsigned slot_bits = 8;
inline constexpr std::size_t slots_per_dictionary = std::size_t{1} << slot_bits;

// The most probes any address of rows needs.
constexpr std::size_t max_probes(std::span<const object_row> rows,
                                 std::uint32_t multiplier) noexcept {
    std::array<bool, slots_per_dictionary> used{};
    std::size_t most = 0;
    for (const auto& r : rows) {
        std::size_t s = home_slot(wire_key(r.address), multiplier, 32 - slot_bits);
        std::size_t probes = 1;
        for (; used[s]; ++probes) s = (s + 1) % slots_per_dictionary;
        used[s] = true;
        most = probes > most ? probes : most;
    }
    return most;
}
constexpr std::uint32_t find_multiplier() noexcept {
    for (std::size_t t = 0; t < 4096; ++t) {
        bool fits = true;
        for (const auto rows : dictionary_rows)
            fits = fits && max_probes(rows, hash_candidate(t)) <= 2;
        if (fits) return hash_candidate(t);
    }
    return 0;
}
inline constexpr std::uint32_t hash_multiplier = find_multiplier();
static_assert(hash_multiplier != 0, "no multiplier finds every address in two probes");

inline constexpr auto address_slots = [] {
    std::array<std::uint8_t, dictionary_count * slots_per_dictionary> t{};
    for (std::size_t d = 0; d < dictionary_count; ++d) {
        for (const auto& r : dictionary_rows[d]) {
            std::size_t s = home_slot(wire_key(r.address), hash_multiplier, 32 - slot_bits);
            while (t[d * slots_per_dictionary + s] != 0) s = (s + 1) % slots_per_dictionary;
            t[d * slots_per_dictionary + s] = codec_row_number(r);
        }
    }
    return t;
}();

// Row s, whose key a 24-bit key matched: not the sentinel. Telling the compiler so (g++ and clang)
// drops the callers' `== 0` tests from the path of a known address (-3 instructions per SDO frame,
// CHANGELOG.md "How we got here").
constexpr std::uint8_t matched_row(std::uint8_t s) noexcept {
    POWERKEY_DETAIL_ASSUME_NOT(s == 0);
    return s;
}

// Per dictionary, which codec rows it has: one bit per codec row number (bit n of word n / 32),
// what scan_codec_row reads in place of the hash slots.
inline constexpr std::size_t codec_row_words = (codec_rows.size() + 31) / 32;
inline constexpr auto dictionary_codec_rows = [] {
    std::array<std::array<std::uint32_t, codec_row_words>, dictionary_count> t{};
    for (std::size_t d = 0; d < dictionary_count; ++d)
        for (const auto& r : dictionary_rows[d]) {
            const std::uint8_t n = codec_row_number(r);
            t[d][n / 32] |= std::uint32_t{1} << (n % 32);
        }
    return t;
}();

// find_codec_row by a scan of the codec rows dictionary d has (a test holds the two to the same
// answer): the lookup under -Os, POWERKEY_DETAIL_SIZE (docs/performance.md, firmware b).
constexpr std::uint8_t scan_codec_row(dictionary d, std::uint32_t key) noexcept {
    key &= 0xFF'FFFF;
    const auto& has = dictionary_codec_rows[static_cast<std::size_t>(d)];
    for (std::size_t n = 1; n < codec_rows.size(); ++n)
        if (((has[n / 32] >> (n % 32)) & 1u) != 0 && codec_rows[n].key == key)
            return matched_row(static_cast<std::uint8_t>(n));
    return 0;
}

// The codec row number at wire address `key` (its low 24 bits, as wire_key makes it) in
// dictionary d, 0 when it has none.
// Two probes, unrolled: every address is found within two (find_multiplier). An empty slot is
// row 0, the sentinel no key matches; a key whose home slot is empty is nowhere (it would have
// been put there: no row is ever removed). Under -Os, the scan above.
constexpr std::uint8_t find_codec_row(dictionary d, std::uint32_t key) noexcept {
    if constexpr (POWERKEY_DETAIL_SIZE) return scan_codec_row(d, key);
    key &= 0xFF'FFFF;
    const std::size_t table = static_cast<std::size_t>(d) * slots_per_dictionary;
    const std::uint32_t home = home_slot(key, hash_multiplier, 32 - slot_bits);
    const std::uint8_t s = address_slots[table + home];
    if (codec_rows[s].key == key) return matched_row(s);
    const std::uint8_t t = address_slots[table + ((home + 1) % slots_per_dictionary)];
    if (codec_rows[t].key == key) return matched_row(t);
    return 0;
}

// Per dictionary and object: the codec row number (the encoder's lookup), and the full row
// index + 1 (find_row); 0 when the dictionary lacks the object.
template <bool Full>
constexpr auto by_object() noexcept {
    std::array<std::array<std::uint8_t, object_count>, dictionary_count> t{};
    for (std::size_t d = 0; d < dictionary_count; ++d) {
        const auto rows = dictionary_rows[d];
        for (std::size_t i = 0; i < rows.size(); ++i)
            t[d][static_cast<std::size_t>(rows[i].id)] =
                Full ? static_cast<std::uint8_t>(i + 1) : codec_row_number(rows[i]);
    }
    return t;
}
inline constexpr auto codec_rows_by_object = by_object<false>();
inline constexpr auto full_rows_by_object = by_object<true>();

// The codec row number of object o in dictionary d, 0 when it has none.
constexpr std::uint8_t find_codec_row(dictionary d, object o) noexcept {
    const auto i = static_cast<std::size_t>(o);
    if (i >= object_count) return 0;
    return codec_rows_by_object[static_cast<std::size_t>(d)][i];
}

// --- one dictionary, known when the program is built ---------------------------------------------
// The same lookups over dictionary D's rows alone (numbered 1.. in their order, 0 the sentinel),
// with the same hash and probes: a program whose model is a template argument (model_constant)
// links these and not the tables of every dictionary.
template <dictionary D>
struct one_dictionary {
    static constexpr std::span<const object_row> full =
        dictionary_rows[static_cast<std::size_t>(D)];
    static_assert(full.size() < 255, "a row number (1..) and the sentinel fit a byte");
    static constexpr auto rows = [] {
        std::array<codec_row, full.size() + 1> t{};
        t[0] = no_codec_row;
        for (std::size_t i = 0; i < full.size(); ++i) t[i + 1] = codec_row_of(full[i]);
        return t;
    }();
    static constexpr auto slots = [] {
        std::array<std::uint8_t, slots_per_dictionary> t{};
        for (std::size_t i = 0; i < full.size(); ++i) {
            std::size_t s = home_slot(wire_key(full[i].address), hash_multiplier, 32 - slot_bits);
            while (t[s] != 0) s = (s + 1) % slots_per_dictionary;
            t[s] = static_cast<std::uint8_t>(i + 1);
        }
        return t;
    }();
    static constexpr auto by_object = [] {
        std::array<std::uint8_t, object_count> t{};
        for (std::size_t i = 0; i < full.size(); ++i)
            t[static_cast<std::size_t>(full[i].id)] = static_cast<std::uint8_t>(i + 1);
        return t;
    }();
    static constexpr std::uint8_t find(std::uint32_t key) noexcept {
        key &= 0xFF'FFFF;
        const std::uint32_t home = home_slot(key, hash_multiplier, 32 - slot_bits);
        const std::uint8_t s = slots[home];
        if (rows[s].key == key) return matched_row(s);
        const std::uint8_t t = slots[(home + 1) % slots_per_dictionary];
        if (rows[t].key == key) return matched_row(t);
        return 0;
    }
    static constexpr std::uint8_t find(object o) noexcept {
        const auto i = static_cast<std::size_t>(o);
        return i < object_count ? by_object[i] : std::uint8_t{0};
    }
};

// A model's layout as a type (its dictionary's lookups chosen by overload): what the codec reads
// for a keypad whose model is a template argument. A codec function that looks rows up takes
// its keypad as `const Layout&`, so that the static type chooses the tables; every other one takes
// the model_layout inside.
template <model M>
struct fixed_layout : model_layout {
    static constexpr powerkey::dictionary dictionary_value = row_of(M).dictionary;
};
template <model M>
inline constexpr fixed_layout<M> fixed_layout_v{layout_of(row_of(M))};
template <class Layout>
inline constexpr bool is_fixed_layout = false;
template <model M>
inline constexpr bool is_fixed_layout<fixed_layout<M>> = true;

// The value kinds of dictionary d's rows, bit k for kind k (every kind has a bit).
static_assert(std::size(enum_names<value_kind>::entries) <= 64);
constexpr std::uint64_t kinds_of(dictionary d) noexcept {
    std::uint64_t has = 0;
    for (const auto& r : dictionary_rows[static_cast<std::size_t>(d)])
        has |= std::uint64_t{1} << static_cast<unsigned>(
                   object_infos[static_cast<std::size_t>(r.id)].kind);
    return has;
}

// The layout a function reads: the one it was given for a run-time model; for a fixed layout the
// constant itself, so that its fields fold in a function not inlined into the caller that named
// the model (the reference parameter alone does not tell the compiler which layout it is).
constexpr const model_layout& known(const model_layout& keypad) noexcept { return keypad; }
template <model M>
constexpr const fixed_layout<M>& known(const fixed_layout<M>&) noexcept {
    return fixed_layout_v<M>;
}

// The codec row number of a key or an object in keypad's dictionary (0: none), and the row.
constexpr std::uint8_t find_codec_row(const model_layout& keypad, std::uint32_t key) noexcept {
    return find_codec_row(keypad.dictionary, key);
}
constexpr std::uint8_t find_codec_row(const model_layout& keypad, object o) noexcept {
    return find_codec_row(keypad.dictionary, o);
}
constexpr const codec_row& codec_row_at(const model_layout&, std::uint8_t i) noexcept {
    return codec_rows[i];
}
template <model M>
constexpr std::uint8_t find_codec_row(const fixed_layout<M>&, std::uint32_t key) noexcept {
    return one_dictionary<row_of(M).dictionary>::find(key);
}
template <model M>
constexpr std::uint8_t find_codec_row(const fixed_layout<M>&, object o) noexcept {
    return one_dictionary<row_of(M).dictionary>::find(o);
}
template <model M>
constexpr const codec_row& codec_row_at(const fixed_layout<M>&, std::uint8_t i) noexcept {
    return one_dictionary<row_of(M).dictionary>::rows[i];
}
}  // namespace detail

// The row of an object in a dictionary; nullopt when the dictionary does not have it.
// (A copy, not a pointer: a null test on the address of a static object is not a constant
// expression under UBSan.)
[[nodiscard]] constexpr std::optional<object_row> find_row(dictionary d, object o) noexcept {
    const auto i = static_cast<std::size_t>(o);
    if (i >= object_count) return std::nullopt;
    const std::uint8_t r = detail::full_rows_by_object[static_cast<std::size_t>(d)][i];
    if (r == 0) return std::nullopt;
    return rows_of(d)[r - 1u];
}

// The row at an address; nullopt when the dictionary has none there (errc::unknown_object).
[[nodiscard]] constexpr std::optional<object_row> find_row(dictionary d,
                                                           canopen::sdo_address a) noexcept {
    const std::uint8_t r = detail::find_codec_row(d, detail::wire_key(a));
    if (r == 0) return std::nullopt;
    return find_row(d, detail::codec_rows[r].id);
}

namespace detail {
// rows_of and find_row of keypad's dictionary: for a fixed_layout, from its own tables alone.
constexpr std::span<const object_row> rows_of(const model_layout& keypad) noexcept {
    return powerkey::rows_of(keypad.dictionary);
}
constexpr std::optional<object_row> find_row(const model_layout& keypad, object o) noexcept {
    return powerkey::find_row(keypad.dictionary, o);
}
constexpr std::optional<object_row> find_row(const model_layout& keypad,
                                             canopen::sdo_address a) noexcept {
    return powerkey::find_row(keypad.dictionary, a);
}
template <model M>
constexpr std::span<const object_row> rows_of(const fixed_layout<M>&) noexcept {
    return one_dictionary<fixed_layout<M>::dictionary_value>::full;
}
constexpr object lookup_key(object o) noexcept { return o; }
constexpr std::uint32_t lookup_key(canopen::sdo_address a) noexcept { return wire_key(a); }
template <model M, class Key>  // an object or an sdo_address
constexpr std::optional<object_row> find_row(const fixed_layout<M>& keypad, Key k) noexcept {
    const std::uint8_t i = find_codec_row(keypad, lookup_key(k));
    if (i == 0) return std::nullopt;
    return rows_of(keypad)[i - 1u];
}
}  // namespace detail

}  // namespace powerkey

#endif  // POWERKEY_KEYPAD_LOOKUP_HPP
