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

#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>

namespace tool {

// --- JSON writing -------------------------------------------------------------------------------

template <class T>
void write_json_value(json::object_writer& w, const T& v) {
    if constexpr (std::is_same_v<T, bool>) {
        w.boolean(v);
    } else if constexpr (std::is_enum_v<T>) {
        if (powerkey::is_named(v))
            w.string(powerkey::to_string(v));
        else
            w.number(static_cast<std::uint64_t>(v));
    } else if constexpr (powerkey::is_index_set<T>::value) {
        w.raw("[");
        bool first = true;
        for (unsigned i = 1; i <= T::max; ++i) {
            if (!v.contains(i)) continue;
            if (!first) w.raw(",");
            first = false;
            w.number(i);
        }
        w.raw("]");
    } else if constexpr (powerkey::is_byte_array<T>::value) {
        std::string hex;
        for (auto b : v) append_hex(hex, b, 2);
        w.string(hex);
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
