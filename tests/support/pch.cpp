// The translation unit that owns tests/support/pch.hpp's precompiled header (tests/CMakeLists.txt):
// every test executable reuses it.
