// powerkey detail: the shape of an enum's name table (names.hpp has the functions over it). Kept
// apart so that a header can give its enum names without pulling in result<T>.
#ifndef POWERKEY_DETAIL_ENUM_TABLE_HPP
#define POWERKEY_DETAIL_ENUM_TABLE_HPP

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

#endif  // POWERKEY_DETAIL_ENUM_TABLE_HPP
