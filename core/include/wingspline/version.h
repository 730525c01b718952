#pragma once
// The package version (from package.json, passed in by CMake), so api.version and the
// compiled core can never disagree.
namespace wingspline {
inline const char* version() noexcept { return WINGSPLINE_VERSION; }
} // namespace wingspline
