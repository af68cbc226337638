// powerkey: the shape of an enum's name table, which each named enum specialises beside its
// definition (names.hpp has the functions over it: to_string, from_string, enum_values). Kept
// apart so that a header can give its enum names without pulling in result<T>.
#ifndef POWERKEY_ENUM_NAMES_HPP
#define POWERKEY_ENUM_NAMES_HPP

#include <string_view>

namespace powerkey {

template <class E>
struct enum_name_entry {
    E value;
    std::string_view name;
};

// Specialised next to each named enum: static constexpr enum_name_entry<E> entries[] = {...};
template <class E>
struct enum_names;

}  // namespace powerkey

// An enum and its names from one list of rows X(name) or X(name, value), written once:
//   #define POWERKEY_ERRC_LIST(X) X(wrong_id_format, 1) X(wrong_id) ...
//   enum class errc : std::uint8_t { POWERKEY_ERRC_LIST(POWERKEY_DETAIL_ENUMERATOR) };
//   POWERKEY_DETAIL_ENUM_NAMES(powerkey::errc, POWERKEY_ERRC_LIST);  // at global scope
// A table with aliases lists them after the first names (POWERKEY_DETAIL_ENUM_ALIAS).
#define POWERKEY_DETAIL_ENUMERATOR(name, ...) name __VA_OPT__(= __VA_ARGS__),
#define POWERKEY_DETAIL_ENUM_NAME(name, ...) {value_type::name, #name},
// A second name for a value, read as well as the first (which is the one written).
#define POWERKEY_DETAIL_ENUM_ALIAS(name, alias) {value_type::name, alias},
// The name table of enum E (its qualified name) from its list, then any aliases:
//   POWERKEY_DETAIL_ENUM_NAMES(E, LIST, POWERKEY_DETAIL_ENUM_ALIAS(kbit_125, "125k"))
#define POWERKEY_DETAIL_ENUM_NAMES(E, LIST, ...)                                                  \
    template <>                                                                                   \
    struct powerkey::enum_names<E> {                                                              \
        using value_type = E;                                                                     \
        static constexpr enum_name_entry<value_type> entries[] = {LIST(POWERKEY_DETAIL_ENUM_NAME) \
                                                                      __VA_ARGS__};               \
    }

#endif  // POWERKEY_ENUM_NAMES_HPP
