// powerkey: the library version, for `#if` checks and for tools that print it.
#ifndef POWERKEY_VERSION_HPP
#define POWERKEY_VERSION_HPP

#define POWERKEY_VERSION_MAJOR 0
#define POWERKEY_VERSION_MINOR 1
#define POWERKEY_VERSION_PATCH 0

#include <string_view>

namespace powerkey {
inline constexpr std::string_view version = "0.1.0";
}  // namespace powerkey

#endif  // POWERKEY_VERSION_HPP
