// powerkey detail: a field that is a view of stored bits. The kind/fields convention calls
// f(name, value) with a reference to each field; where a value is stored packed (an SDO value's
// wire number), the view is made in a temporary, given to f, and written back when the message is
// being filled in (a non-const Self), so readers and writers of fields need not know the packing.
#ifndef POWERKEY_DETAIL_PROXY_HPP
#define POWERKEY_DETAIL_PROXY_HPP

#include <string_view>
#include <type_traits>
#include <utility>

namespace powerkey::detail {

template <class T, class Self, class F, class Get, class Set>
constexpr void proxy_field(Self& self, F& f, std::string_view name, Get get, Set set) {
    T v = get(self);
    if constexpr (std::is_const_v<Self>) {
        f(name, std::as_const(v));
    } else {
        f(name, v);
        set(self, v);
    }
}

}  // namespace powerkey::detail

#endif  // POWERKEY_DETAIL_PROXY_HPP
