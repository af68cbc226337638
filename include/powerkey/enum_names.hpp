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

#endif  // POWERKEY_ENUM_NAMES_HPP
