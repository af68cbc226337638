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
//   template <> struct enum_names<errc> {
//       using value_type = errc;
//       static constexpr enum_name_entry<errc> entries[] =
//       {POWERKEY_ERRC_LIST(POWERKEY_DETAIL_ENUM_NAME)};
//   };
// An enum whose names have aliases (two names for one value) writes its table by hand.
#define POWERKEY_DETAIL_ENUMERATOR(name, ...) name __VA_OPT__(= __VA_ARGS__),
#define POWERKEY_DETAIL_ENUM_NAME(name, ...) {value_type::name, #name},

namespace powerkey {}  // namespace powerkey

#endif  // POWERKEY_ENUM_NAMES_HPP
