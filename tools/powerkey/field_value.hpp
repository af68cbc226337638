// powerkey tool: field values in JSON, both ways: decode --json writes them (json_writer.hpp),
// encode --json reads them (nlohmann/json). Text values: field_text.hpp.
//   bool                  true/false
//   integers, bounded     numbers; a string is read as text ("3Ah")
//   enums                 their name, or the number for a value without a name
//   std::array<uint8_t>   a hex string "72696E"
//   index_set<N>          an array [1,7]
#ifndef POWERKEY_TOOL_FIELD_VALUE_HPP
#define POWERKEY_TOOL_FIELD_VALUE_HPP

#include "field_text.hpp"
#include "json_writer.hpp"

#include <nlohmann/json.hpp>
#include <powerkey/fields.hpp>

#include <array>
#include <bit>
#include <cstdint>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>

namespace tool {

// --- JSON writing -------------------------------------------------------------------------------

template <class Writer, class T>
void write_json_value(Writer& w, const T& v) {
    if constexpr (std::is_same_v<T, bool>) {
        w.boolean(v);
    } else if constexpr (std::is_enum_v<T>) {
        if (powerkey::is_named(v))
            w.string(powerkey::to_string(v));
        else
            w.number(static_cast<std::uint64_t>(v));
    } else if constexpr (powerkey::is_index_set<T>::value) {
        w.raw('[');
        bool first = true;
        for (auto bits = v.mask(); bits != 0; bits &= bits - 1) {  // bit 0 is number 1
            if (!first) w.raw(',');
            first = false;
            w.number(static_cast<unsigned>(std::countr_zero(bits)) + 1);
        }
        w.raw(']');
    } else if constexpr (powerkey::is_byte_array<T>::value) {
        char hex[2 * std::tuple_size_v<T>];
        std::size_t n = 0;
        for (const auto b : v) {
            hex[n++] = upper_hex[b >> 4];
            hex[n++] = upper_hex[b & 15];
        }
        w.string(std::string_view(hex, n));
    } else if constexpr (powerkey::is_bounded<T>::value) {
        w.number(v.value());
    } else {
        static_assert(std::is_integral_v<T>, "a field type outside the kind/fields convention");
        w.number(static_cast<std::uint64_t>(v));
    }
}

template <class T>
std::string set_from_json(T& v, const nlohmann::json& j, std::string_view name = "") {
    if (j.is_string()) return set_from_text(v, j.get_ref<const std::string&>(), name);
    if (j.is_number_unsigned()) return set_from_number(v, j.get<std::uint64_t>(), name);
    if (j.is_number_integer()) return "a negative number";
    if (j.is_boolean()) {
        if constexpr (std::is_same_v<T, bool>) return v = j.get<bool>(), "";
        return "unexpected true/false";
    }
    if (j.is_array()) {
        if constexpr (powerkey::is_index_set<T>::value) {
            T set{};
            for (const auto& item : j) {
                if (!item.is_number_unsigned() || item.get<std::uint64_t>() < 1 ||
                    item.get<std::uint64_t>() > T::max)
                    return "expected numbers 1.." + std::to_string(T::max);
                set.insert(static_cast<unsigned>(item.get<std::uint64_t>()));
            }
            v = set;
            return "";
        }
        return "unexpected array";
    }
    return "unexpected value";
}

}  // namespace tool

#endif
