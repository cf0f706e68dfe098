// curvebench.hpp: the whole reference library in one include.
//
// What: every public header of curvebench::curvebench - core (points, the curve concept, errors,
// Real utilities, any_curve, result statuses), basis (Bernstein, cubic basis matrices, constraint
// solver), curves (one family per header), the property audit, arclength (quadrature, lengths, inversion,
// parameterization), channel (keyframe channels: keys, segments, extrapolation and the curve
// view; the time solvers of a Bezier segment; the tool models: CSS easing, glTF 2.0 samplers,
// Penner's easing equations as Blender applies them, Blender's F-curves, Maya's animCurves, USD's
// Ts splines), motion (ease functions, keyframes, motion along a path) and reference (the 50-digit
// type real50, conversion to it, reference arc length, closed forms).
// Not included: io/ (JSON specs and the family registry), which needs nlohmann/json and lives in
// its own target curvebench::io (include "curvebench/io/spec.hpp" and link curvebench::io), and
// the private detail/ headers.
// Cost: including everything costs compile time (real50 and Boost.Math are large); code that
// needs one family compiles faster with that family's header alone. Every header listed here is
// also compiled on its own by the test suite (tests/CMakeLists.txt, header self-containment).
#pragma once

#include "curvebench/core/any_curve.hpp"
#include "curvebench/core/curve.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"
#include "curvebench/core/result_status.hpp"

#include "curvebench/basis/bernstein.hpp"
#include "curvebench/basis/constraints.hpp"
#include "curvebench/basis/cubic_matrices.hpp"

#include "curvebench/curves/bezier.hpp"
#include "curvebench/curves/bspline.hpp"
#include "curvebench/curves/cardinal_spline.hpp"
#include "curvebench/curves/composite_bezier.hpp"
#include "curvebench/curves/hermite_spline.hpp"
#include "curvebench/curves/kochanek_bartels.hpp"
#include "curvebench/curves/lagrange.hpp"
#include "curvebench/curves/natural_cubic_spline.hpp"
#include "curvebench/curves/nurbs.hpp"
#include "curvebench/curves/piecewise_cubic.hpp"
#include "curvebench/curves/polyline.hpp"
#include "curvebench/curves/rational_bezier.hpp"

#include "curvebench/analysis/property_audit.hpp"

#include "curvebench/arclength/adaptive_subdivision.hpp"
#include "curvebench/arclength/forward_difference.hpp"
#include "curvebench/arclength/gauss_kronrod.hpp"
#include "curvebench/arclength/gauss_legendre.hpp"
#include "curvebench/arclength/length.hpp"
#include "curvebench/arclength/newton_inversion.hpp"
#include "curvebench/arclength/parameterization.hpp"
#include "curvebench/arclength/result.hpp"

#include "curvebench/channel/blender.hpp"
#include "curvebench/channel/channel.hpp"
#include "curvebench/channel/css_easing.hpp"
#include "curvebench/channel/gltf.hpp"
#include "curvebench/channel/maya.hpp"
#include "curvebench/channel/penner.hpp"
#include "curvebench/channel/time_solver.hpp"
#include "curvebench/channel/tool_model.hpp"
#include "curvebench/channel/tools/blender.hpp"
#include "curvebench/channel/tools/css.hpp"
#include "curvebench/channel/tools/exact.hpp"
#include "curvebench/channel/tools/gltf.hpp"
#include "curvebench/channel/tools/maya.hpp"
#include "curvebench/channel/tools/usd.hpp"
#include "curvebench/channel/usd.hpp"

#include "curvebench/motion/distance_time.hpp"
#include "curvebench/motion/keyframes.hpp"
#include "curvebench/motion/monotone_cubic.hpp"
#include "curvebench/motion/motion_path.hpp"

#include "curvebench/reference/analytic_curves.hpp"
#include "curvebench/reference/arc_length.hpp"
#include "curvebench/reference/closed_forms.hpp"
#include "curvebench/reference/convert.hpp"
#include "curvebench/reference/multiprecision.hpp"
