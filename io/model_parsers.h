// Internal to io/: one parser per format, each feeding a SoupBuilder from the whole file in memory.
// They throw io::Error through SoupBuilder::fail; read_model.cpp calls them and finishes the soup.
#pragma once

#include <string_view>

#include "soup_builder.h"

namespace delpsc::io::detail {

void parse_off(std::string_view bytes, SoupBuilder& out);
void parse_obj(std::string_view bytes, SoupBuilder& out);
void parse_stl(std::string_view bytes, SoupBuilder& out);
/// Whether the size of `bytes` is exactly 84 + 50 n for the count n a binary STL header holds:
/// near-certain proof of a binary STL, whatever its free-form header starts with.
bool stl_size_proves_binary(std::string_view bytes);
void parse_ply(std::string_view bytes, SoupBuilder& out);

/// Largest vertex count a soup can hold: indices are uint32.
inline constexpr std::uint64_t kMaxVertices = 0xffffffffULL;

}  // namespace delpsc::io::detail
