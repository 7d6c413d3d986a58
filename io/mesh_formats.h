// Internal to io/: one function per output format, each appending the whole file to a string.
// write_mesh.cpp validates the mesh and dispatches on the extension.
#pragma once

#include <cstdint>
#include <string>

#include "surface_mesh.h"

namespace delpsc::io::detail {

void format_off(const SurfaceMesh& mesh, std::string& out);
void format_obj(const SurfaceMesh& mesh, std::string& out);
void format_ply(const SurfaceMesh& mesh, std::string& out);
void format_stl(const SurfaceMesh& mesh, std::string& out);
void format_medit(const SurfaceMesh& mesh, std::string& out);
void format_vtu(const SurfaceMesh& mesh, std::string& out);

/// Appends the shortest decimal form that reads back as exactly `v` (std::to_chars), so text
/// formats round-trip without 17-digit noise.
void append_number(std::string& out, double v);
void append_number(std::string& out, std::int64_t v);
inline void append_number(std::string& out, std::uint32_t v) { append_number(out, std::int64_t{v}); }
inline void append_number(std::string& out, std::int32_t v) { append_number(out, std::int64_t{v}); }

}  // namespace delpsc::io::detail
