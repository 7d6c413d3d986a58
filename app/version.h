#pragma once
namespace delpsc {
inline constexpr const char* kVersion = "0.1.0";
}
