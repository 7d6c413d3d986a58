// Internal to io/: loading and storing little- and big-endian scalars from unaligned bytes
// (binary STL and PLY), whatever the byte order of the machine.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace delpsc::io::detail {

template <class U>
constexpr U byte_swap(U v) {
  static_assert(std::is_unsigned_v<U>);
  if constexpr (sizeof(U) == 1) return v;
  if constexpr (sizeof(U) == 2) return static_cast<U>(__builtin_bswap16(v));
  if constexpr (sizeof(U) == 4) return static_cast<U>(__builtin_bswap32(v));
  if constexpr (sizeof(U) == 8) return static_cast<U>(__builtin_bswap64(v));
}

template <class T>
using same_size_uint = std::conditional_t<
    sizeof(T) == 1, std::uint8_t,
    std::conditional_t<sizeof(T) == 2, std::uint16_t,
                       std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;

/// Reads a T stored at p (any alignment) in the given byte order.
template <class T>
T load(const char* p, std::endian order) {
  using U = same_size_uint<T>;
  U u;
  std::memcpy(&u, p, sizeof u);
  if (order != std::endian::native) u = byte_swap(u);
  return std::bit_cast<T>(u);
}

/// Appends the bytes of v in little-endian order to a byte string.
template <class T, class String>
void append_little_endian(String& out, T v) {
  using U = same_size_uint<T>;
  U u = std::bit_cast<U>(v);
  if (std::endian::native != std::endian::little) u = byte_swap(u);
  char bytes[sizeof u];
  std::memcpy(bytes, &u, sizeof u);
  out.append(bytes, sizeof u);
}

}  // namespace delpsc::io::detail
