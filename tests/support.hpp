// Test support shared by every test file: doctest printers for the library's types, so that a
// failing CHECK prints an errc by name, a frame in candump form and a message as the description
// writer does; and the row runner every table uses, so that a failing row names itself both at
// compile time and at run time.
//
//   constexpr bool decodes(const row& r) { ... }             // one check, written once
//   static_assert(all_rows_pass<first_failing(rows, decodes), std::size(rows)>);
//                                                 // the compiler names the first failing row
//   TEST_CASE("...") { check_rows(rows, decodes); }            // doctest prints section + frame
#ifndef POWERKEY_TESTS_SUPPORT_HPP
#define POWERKEY_TESTS_SUPPORT_HPP

#include <doctest/doctest.h>

#include <powerkey/can/candump.hpp>
#include <powerkey/describe.hpp>
#include <powerkey/error.hpp>
#include <powerkey/keypad/messages.hpp>
#include <powerkey/names.hpp>
#include <powerkey/result.hpp>

#include <array>
#include <cstddef>
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

}  // namespace powerkey_tests

#endif  // POWERKEY_TESTS_SUPPORT_HPP
