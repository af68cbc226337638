// Test support shared by every test file: doctest printers for the library's types, so that a
// failing CHECK prints an errc by name, a frame in candump form and a message as the description
// writer does; the row runner every table uses, so that a failing row names itself both at
// compile time and at run time; the rows of frames one decoder refuses; and the check of an
// enum's name table against rows from the manuals.
//
//   constexpr bool decodes(const row& r) { ... }             // one check, written once
//   static_assert(all_rows_pass<first_failing(rows, decodes), std::size(rows)>);
//                                                 // the compiler names the first failing row
//   TEST_CASE("...") { check_rows(rows, decodes); }            // doctest prints section + frame
#ifndef POWERKEY_TESTS_SUPPORT_HPP
#define POWERKEY_TESTS_SUPPORT_HPP

#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/canopen/sdo.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/error.hpp>
#include <powerkey/keypad/messages.hpp>
#include <powerkey/names.hpp>
#include <powerkey/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

namespace doctest {

template <>
struct StringMaker<powerkey::errc> {
    static String convert(powerkey::errc e) {
        const auto n = powerkey::to_string(e);
        return n.empty() ? String("errc(?)") : String(n.data(), static_cast<unsigned>(n.size()));
    }
};

template <>
struct StringMaker<powerkey::can::frame> {
    static String convert(const powerkey::can::frame& f) {
        const auto t = powerkey::can::format_candump(f);
        return String(t.view().data(), static_cast<unsigned>(t.view().size()));
    }
};

template <>
struct StringMaker<powerkey::message> {
    static String convert(const powerkey::message& m) {
        std::array<char, 256> buf{};
        const auto d = powerkey::describe(m, powerkey::canopen::default_node_id, buf);
        const std::string_view v = d ? *d : std::string_view(buf.data(), buf.size());
        return String(v.data(), static_cast<unsigned>(v.size()));
    }
};

template <class T>
struct StringMaker<powerkey::result<T>> {
    static String convert(const powerkey::result<T>& r) {
        if (!r) return String("error ") + StringMaker<powerkey::errc>::convert(r.error());
        if constexpr (std::is_same_v<T, powerkey::message> ||
                      std::is_same_v<T, powerkey::can::frame> || std::is_same_v<T, powerkey::errc>)
            return StringMaker<T>::convert(*r);
        else
            return String("a value");
    }
};

}  // namespace doctest

namespace powerkey_tests {

// Index of the first row for which check(row) is false; N when every row passes.
template <class Row, std::size_t N, class Check>
constexpr std::size_t first_failing(const Row (&rows)[N], Check check) {
    for (std::size_t i = 0; i < N; ++i)
        if (!check(rows[i])) return i;
    return N;
}

// true when FirstFailing == Rows; otherwise the static_assert inside fails, and both g++ and
// clang++ print the instantiation rows_checked<FirstFailing, Rows>: the index of the failing row.
template <std::size_t FirstFailing, std::size_t Rows>
struct rows_checked {
    static_assert(FirstFailing == Rows, "a table row fails its check: rows_checked<row, rows>");
    static constexpr bool value = true;
};
template <std::size_t FirstFailing, std::size_t Rows>
inline constexpr bool all_rows_pass = rows_checked<FirstFailing, Rows>::value;

// Runs check over every row at run time (so coverage and sanitizers see it), naming a failing
// row by its section and frame.
template <class Row, std::size_t N, class Check>
void check_rows(const Row (&rows)[N], Check check) {
    for (std::size_t i = 0; i < N; ++i) {
        const auto& r = rows[i];
        INFO("row ", i, ": ", std::string(r.section), "  ", std::string(r.frame));
        CHECK(check(r));
    }
}

constexpr powerkey::can::frame frame_of(std::string_view text) {
    return powerkey::can::parse_candump(text).value();
}

// An expedited SDO of `size` bytes (1, 2 or 4) to or from keypad `node`: a write (600h + node) or
// the value read (580h + node) at `address`, its bytes 4..7 the little-endian `data` (bytes past
// `size` too, so that a walker can set them).
constexpr powerkey::can::frame expedited_frame(powerkey::canopen::node_id node,
                                               powerkey::canopen::sdo_address address,
                                               std::uint8_t size, std::uint32_t data, bool write) {
    powerkey::canopen::expedited_data d{powerkey::canopen::expedited_size::make(size).value(), {}};
    for (std::size_t i = 0; i < 4; ++i) d.bytes[i] = static_cast<std::uint8_t>(data >> (8 * i));
    if (write)
        return powerkey::canopen::encode(node, powerkey::canopen::sdo_download_request{address, d});
    return powerkey::canopen::encode(node, powerkey::canopen::sdo_upload_response{address, d});
}

// --- frames a decoder refuses --------------------------------------------------------------------

// A frame and the error one decoder refuses it with; refused_by(decode) is the row check.
struct bad_row {
    std::string_view section;
    std::string_view frame;
    powerkey::errc error;
};
template <class Decode>
constexpr auto refused_by(Decode decode) {
    return [decode](const bad_row& r) { return decode(frame_of(r.frame)) == r.error; };
}

// --- name tables ---------------------------------------------------------------------------------

// One value of an enum's name table: the byte a manual gives it and the name the library prints;
// an alias is a second name of the same value, which from_string takes and to_string never prints.
struct name_row {
    std::string_view section;  // where the value's byte comes from
    std::uint8_t byte;         // the value on the wire (or the enumerator's number)
    std::string_view name;
    bool alias = false;
};

// The name table of E is the rows, written in the table's order:
//   - every row's name reads back to its value (aliases too), and a non-alias row's value prints
//     as its name and is_named;
//   - enum_values<E>() lists the non-alias rows' values, in that order, once each;
//   - `unnamed` (a value with no row) prints "" and is not named; text that names nothing (an
//     unknown name, the empty string, a name in upper case or with a space) reads back as nullopt.
template <class E, std::size_t N>
constexpr bool name_table_is(const name_row (&rows)[N], std::uint8_t unnamed) {
    using powerkey::enum_values;
    using powerkey::from_string;
    using powerkey::is_named;
    using powerkey::to_string;
    std::size_t values = 0;
    for (const auto& r : rows) {
        const auto v = static_cast<E>(r.byte);
        if (from_string<E>(r.name) != std::optional<E>(v)) return false;
        if (r.alias) {
            if (to_string(v) == r.name) return false;
            continue;
        }
        if (to_string(v) != r.name || !is_named(v)) return false;
        const auto listed = enum_values<E>();
        if (values >= listed.size() || listed[values] != v) return false;
        ++values;
    }
    if (enum_values<E>().size() != values) return false;
    const auto u = static_cast<E>(unnamed);
    if (!to_string(u).empty() || is_named(u)) return false;
    return !from_string<E>("no_such_name") && !from_string<E>("") && !from_string<E>("RED") &&
           !from_string<E>(" red");
}

}  // namespace powerkey_tests

#endif  // POWERKEY_TESTS_SUPPORT_HPP
