// The precompiled header of the test executables (tests/CMakeLists.txt, CURVEBENCH_PCH): the
// third-party and standard headers that nearly every test parses, and nothing of curvebench's own,
// so that editing a curvebench header never rebuilds it. Parsing these took 16 % of the CPU time of
// a test's compilation (test_channel.cpp: 61 s user without, 43 s with). tests/CMakeLists.txt reads
// the `#include <...>` lines below and precompiles those headers by name (a line of another form is
// not precompiled).
#pragma once

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/next.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/eigen.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <span>
#include <string>
#include <vector>
