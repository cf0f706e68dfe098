// The property audit (curvebench/analysis/property_audit.hpp) run on every curve family in the tree,
// compared with seed 001's table. Each family's measured row (tests/tools/property_families.cpp,
// the rows of docs/properties.md) is pinned; where it differs from the seed, a comment says why.
// The last test checks that docs/properties.md holds the table measured now. The functions for one
// property each are tested alone in test_analysis_properties.cpp.
#include "tools/property_families.hpp"

#include "harness/audit_table.hpp"

#include "curvebench/analysis/property_audit.hpp"
#include "curvebench/curves/bspline.hpp"
#include "curvebench/curves/cardinal_spline.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace cb = curvebench;
namespace an = curvebench::analysis;
namespace pf = curvebench::property_families;
using pf::list2;
using pf::P2;
using pf::span2;
using report = an::property_report<double>;

namespace {

// Seed 001's table, transcribed: interpolates / local / continuity / affine / convex hull / VD.
struct seed_row {
  const char* family;
  const char* interpolates;
  bool local;
  int continuity;
  bool affine;
  const char* convex;  // "yes", "no", "n/a"
  const char* vd;
};
constexpr seed_row seed_hermite{"Hermite", "all", true, 1, true, "n/a", "n/a"};
constexpr seed_row seed_cardinal{"Cardinal (Catmull-Rom)", "all but ends", true, 1, true, "no", "no"};
constexpr seed_row seed_bezier{"Bezier", "ends only", false, 1, true, "yes", "yes"};
constexpr seed_row seed_natural{"natural", "all", false, 2, true, "n/a", "n/a"};
constexpr seed_row seed_bspline{"B-Splines", "none", true, 2, true, "yes", "yes"};

// The table's rows, measured on first use (by whichever test runs first, or alone).
const std::vector<pf::family_row>& rows() {
  static const std::vector<pf::family_row> r = pf::measure_all();
  return r;
}

const report& row(const std::string& label) {
  for (const pf::family_row& r : rows())
    if (r.label == label) return r.report;
  throw std::out_of_range("no row labelled '" + label + "' in tests/tools/property_families.cpp");
}

// Checks a measured report against expected values (the pinned answer).
template <class Real>
void expect_row(const an::property_report<Real>& r, const char* interpolates, bool local, int continuity,
                bool one_piece, bool affine, const char* convex, const char* vd) {
  EXPECT_STREQ(an::to_string(r.interpolation.kind), interpolates);
  EXPECT_EQ(r.local_control.local, local);
  EXPECT_EQ(r.continuity.one_piece, one_piece);
  if (!one_piece) {
    EXPECT_EQ(r.continuity.order, continuity);
  }
  EXPECT_EQ(r.affine.invariant, affine) << "deviation " << static_cast<double>(r.affine.deviation);
  EXPECT_STREQ(an::to_string(r.convex_hull.verdict), convex)
      << "hull violation " << static_cast<double>(r.convex_hull.violation);
  EXPECT_STREQ(an::to_string(r.variation_diminishing.verdict), vd)
      << "worst excess " << r.variation_diminishing.worst_excess;
}

void expect_seed(const report& r, const seed_row& s, bool one_piece = false) {
  SCOPED_TRACE(s.family);
  expect_row(r, s.interpolates, s.local, s.continuity, one_piece, s.affine, s.convex, s.vd);
}

}  // namespace

// B-splines. Seed: interpolates none, local, C2, affine, hull, VD. The uniform (unclamped) cubic
// measures exactly the seed's row. The clamped (open) knot vector used in practice interpolates
// its end points: the seed's "no" is about the uniform B-spline; we pin both.
TEST(property_audit, bspline) {
  expect_seed(row("B-spline, cubic, uniform knots"), seed_bspline);
  // The seed's "no" is for generic data: with three evenly spaced collinear points the uniform cubic
  // passes through the middle one ((P0 + 4 P1 + P2) / 6 = P1 at a knot), which the audit measures.
  list2 collinear = pf::data();
  collinear[2] = P2(2, 0);
  const auto col = an::audit_properties<double, 2>(pf::uniform_cubic_bspline, collinear);
  EXPECT_EQ(col.interpolation.kind, an::interpolation_kind::partial);
  EXPECT_LT(col.interpolation.distance[1], 1e-12);
  const report& c = row("B-spline, cubic, clamped knots");
  expect_row(c, "ends only", true, 2, false, true, "yes", "yes");  // differs from the seed: clamped ends
  // Each control point moves at most m = 4 spans (of 7 on the clamped vector): local support.
  for (std::size_t i = 0; i < pf::data().size(); ++i) EXPECT_LE(c.local_control.moved_fraction[i], 4.0 / 7 + 0.01) << i;
  // The moved range of the middle point P_5 is its support [t_5, t_9] = [2/7, 6/7] (grid resolution).
  EXPECT_NEAR(c.local_control.moved_range[5].lo, 2.0 / 7, 1.0 / (7 * 48) + 1e-12);
  EXPECT_NEAR(c.local_control.moved_range[5].hi, 6.0 / 7, 1.0 / (7 * 48) + 1e-12);
  // C2 and not C3 at every interior knot (the third derivative of a cubic B-spline jumps).
  for (const auto& k : c.continuity.knots) EXPECT_EQ(k.order, 2) << k.u;
}

// NURBS (not in the seed's cubic table; seed 001 mentions them for perspective maps). With positive
// weights the basis R_i = w_i N_i / sum w_j N_j is non-negative, locally supported and sums to 1,
// so the clamped B-spline's row holds: ends only, local, C2, affine, hull, VD.
TEST(property_audit, nurbs) {
  expect_row(row("NURBS, cubic, clamped, weights 0.5..2.5"), "ends only", true, 2, false, true, "yes", "yes");
}

// Bezier. Seed: ends only, not local, C1, affine, hull, VD. A single Bezier curve of degree 9 is
// one polynomial piece: it has no joints, so no continuity order at knots to measure (it is C-inf);
// the seed's C1 is for cubic Bezier segments joined with collinear handles (composite Bezier).
TEST(property_audit, bezier) {
  const report& r = row("Bezier, single, degree 9");
  expect_seed(r, seed_bezier, true);
  // Every Bernstein polynomial is non-zero on (0, 1): the middle points move the whole curve.
  for (std::size_t i = 2; i + 2 < pf::data().size(); ++i) EXPECT_EQ(r.local_control.moved_fraction[i], 1.0) << i;
  expect_row(row("rational Bezier, degree 9, weights 0.5..2.5"), "ends only", false, 0, true, true, "yes", "yes");
}

// Hermite chain (seed 001's alternating points and tangents). Seed: all, local, C1, affine, n/a, n/a.
// Interpolation is counted on the point items only; affine maps move tangents by the linear part.
TEST(property_audit, hermite_chain) { expect_seed(row("Hermite chain (points + tangents)"), seed_hermite); }

// Cardinal / Catmull-Rom. Seed: all but ends, local, C1, affine, no hull, no VD.
TEST(property_audit, cardinal_catmull_rom) {
  // Seed 001's construction (end points only shape the end tangents) measures the seed's row.
  expect_seed(row("Catmull-Rom, seed 001 ends (n - 3 segments)"), seed_cardinal);
  // With phantom end points (seed 002's extrapolation) every point is interpolated: differs from
  // the seed's "except endpoints" only because the end points now get segments of their own.
  expect_row(row("Catmull-Rom, phantom ends, uniform"), "all", true, 1, false, true, "no", "no");
  // Centripetal knots (alpha = 1/2) depend on the distances between points, which an affine map
  // that is not a similarity changes: the rebuilt curve is not the mapped curve. Measured: not
  // affine invariant (the seed's row assumes uniform knots). Also, moving one point changes all
  // later knots, so every sample moves in parameter: not local in u (the shape still is).
  const report& c = row("Catmull-Rom, centripetal (alpha = 1/2)");
  expect_row(c, "all", false, 1, false, false, "no", "no");
  EXPECT_GT(c.affine.deviation, 1e-3);
}

// Kochanek-Bartels (not in the seed's table). Tension and bias keep C1 (the time-adjusted tangents
// are equal on both sides); continuity c != 0 makes incoming and outgoing tangents differ: C0.
TEST(property_audit, kochanek_bartels) {
  expect_row(row("Kochanek-Bartels, t = 0.25, c = 0, b = -0.5"), "all", true, 1, false, true, "no", "no");
  expect_row(row("Kochanek-Bartels, c = 0.5"), "all", true, 0, false, true, "no", "no");
}

// Natural cubic spline. Seed: all, not local, C2, affine, n/a, n/a. The seed marks hull and VD
// "n/a" (it treats the family like Hermite, whose controls include tangents); its controls are
// points only, so the audit measures them: the C2 interpolant overshoots the step (out of the
// hull) and a line just below y = 0 cuts it twice: no, no.
TEST(property_audit, natural_cubic_spline) {
  const report& r = row("natural cubic spline (natural ends)");
  expect_row(r, seed_natural.interpolates, seed_natural.local, seed_natural.continuity, false, seed_natural.affine,
             "no", "no");
  // Not local: every point moves the whole curve (the influence decays, ~0.27 per segment, but
  // stays far above the detection threshold across ten points).
  for (std::size_t i = 0; i < pf::data().size(); ++i) EXPECT_EQ(r.local_control.moved_fraction[i], 1.0) << i;
}

// Composite Bezier (the seed's Bezier row is about joined cubic segments: "C1"), built two ways
// from the same ten items (see property_families.cpp): shared joints (C0, no handle constraint)
// and implied midpoint joints (C1 by construction).
// Measured, and different from the seed's single-curve "not local": a composite chain IS local (an
// item moves at most the two segments that contain it); a single degree-9 Bezier is not.
// Interpolation: shared joints pass through P0, P3, P6, P9 (partial); implied joints only through
// the two end items (ends only, as the seed's row).
TEST(property_audit, composite_bezier) {
  const report& c0 = row("composite Bezier, cubic, shared joints");
  expect_row(c0, "partial", true, 0, false, true, "yes", "yes");
  for (std::size_t i : {0u, 3u, 6u, 9u}) EXPECT_LT(c0.interpolation.distance[i], 1e-12) << i;
  expect_row(row("composite Bezier, cubic, implied midpoint joints"), "ends only", true, 1, false, true, "yes", "yes");
}

// Lagrange interpolation (seed 001: "high degree ones are too wiggly"): one polynomial of degree 9
// through all ten points at equispaced parameters. All interpolated, not local (every Lagrange basis
// polynomial is non-zero almost everywhere), one piece, affine invariant (the basis sums to 1), and
// it oscillates out of the hull and across lines the polygon never crosses.
TEST(property_audit, lagrange) {
  expect_row(row("Lagrange, degree 9, equispaced"), "all", false, 0, true, true, "no", "no");
}

// Polyline (seed 001 lists it among the representations, not in the cubic table): it passes through
// its vertices, each vertex moves only its two segments, C0 with slope jumps, and it is its own
// control polygon, so hull and VD hold trivially. The linear B-spline (order 2, clamped) is the
// same curve on other parameters and measures the same row.
TEST(property_audit, polyline) {
  expect_row(row("polyline"), "all", true, 0, false, true, "yes", "yes");
  expect_row(row("B-spline, linear (order 2, clamped)"), "all", true, 0, false, true, "yes", "yes");
}

// The cubic B-spline converted to the piecewise_cubic engine measures the same row (the audit sees
// only the curve interface, and the conversion keeps the curve).
TEST(property_audit, bspline_through_engine) {
  const auto r = an::audit_properties<double, 2>(
      [](span2 p) { return pf::uniform_cubic_bspline(p).to_piecewise_cubic(); }, pf::data());
  expect_row(r, "none", true, 2, false, true, "yes", "yes");
}

// The audit on constructed cases with known answers: a jump (C-1), and a family that is not affine
// invariant; and its errors.
TEST(property_audit, machinery_known_answers) {
  const list2& data = pf::data();
  // A cubic B-spline with a knot of multiplicity 4 in the middle jumps there: continuity -1.
  const auto jump = an::audit_properties<double, 2>(
      [](span2 p) {
        return cb::bspline<double, 2>(4, {0, 0, 0, 0, 1, 2, 2, 2, 2, 3, 4, 4, 4, 4}, list2(p.begin(), p.end()));
      },
      data);
  ASSERT_FALSE(jump.continuity.one_piece);
  // The knot 2 (multiplicity 4) is the discontinuity; 1 and 3 (simple knots) are C2.
  ASSERT_EQ(jump.continuity.knots.size(), 3u);
  EXPECT_EQ(jump.continuity.knots[0].order, 2);
  EXPECT_EQ(jump.continuity.knots[1].u, 2.0);
  EXPECT_EQ(jump.continuity.knots[1].order, -1);
  EXPECT_EQ(jump.continuity.knots[2].order, 2);
  EXPECT_EQ(jump.continuity.order, -1);
  EXPECT_NE(cb::harness::audit_markdown_row("jump", jump).find("| discontinuous |"), std::string::npos);
  // A "family" that squares x: not affine invariant, and the deviation says by how much.
  const auto squares = an::audit_properties<double, 2>(
      [](span2 p) {
        list2 q(p.begin(), p.end());
        for (auto& x : q) x[0] = x[0] * x[0] / 9.0;
        return pf::uniform_cubic_bspline(q);
      },
      data);
  EXPECT_FALSE(squares.affine.invariant);
  EXPECT_GT(squares.affine.deviation, 1e-3);
  // Bad input.
  const std::vector<an::control_role> short_roles(3, an::control_role::point);
  try {
    (void)an::audit_properties<double, 2>(pf::uniform_cubic_bspline, data, short_roles);
    ADD_FAILURE() << "roles of the wrong length accepted";
  } catch (const cb::invalid_input& e) {
    EXPECT_STREQ(e.what(), "roles: 3 given, must match items: 10");
  }
  auto opt = an::audit_options<double>::defaults();
  opt.samples_per_segment = 1;
  try {
    (void)an::audit_properties<double, 2>(pf::uniform_cubic_bspline, data, {}, opt);
    ADD_FAILURE() << "samples_per_segment = 1 accepted";
  } catch (const cb::invalid_input& e) {
    EXPECT_STREQ(e.what(), "samples_per_segment = 1: must be >= 2");
  }
}

// The audit is templated on Real like the rest of the library: the same verdicts in float and
// long double (tolerances scale with eps(Real), see audit_options::defaults).
template <class Real>
void audit_in(const char* type_name) {
  using P = cb::point<Real, 2>;
  cb::point_list<Real, 2> d;
  for (const P2& q : pf::data()) d.push_back(cb::point_cast<Real>(q));
  const auto b = an::audit_properties<Real, 2>(
      [](std::span<const P> p) {
        return cb::bspline<Real, 2>(4, cb::bspline_clamped_knots<Real>(p.size(), 4, Real(0), Real(1)),
                                    cb::point_list<Real, 2>(p.begin(), p.end()));
      },
      d);
  SCOPED_TRACE(type_name);
  expect_row(b, "ends only", true, 2, false, true, "yes", "yes");
  const auto c = an::audit_properties<Real, 2>(
      [](std::span<const P> p) { return cb::cardinal_spline<Real, 2>(cb::point_list<Real, 2>(p.begin(), p.end())); },
      d);
  expect_row(c, "all", true, 1, false, true, "no", "no");
}

TEST(property_audit, same_verdicts_in_float_and_long_double) {
  audit_in<float>("float");
  audit_in<long double>("long double");
}

// The table of docs/properties.md is the one measured now. It measures every family itself, so it
// passes or fails the same when run alone (--gtest_filter=analysis_table.*) or after the others.
TEST(analysis_table, document_holds_the_measured_table) {
  const std::vector<pf::family_row> fresh = pf::measure_all();
  std::set<std::string> labels;
  for (const pf::family_row& r : fresh) EXPECT_TRUE(labels.insert(r.label).second) << "label twice: " << r.label;
  const std::string measured = pf::markdown_table(fresh);
  const std::string path = pf::document_path();
  std::ifstream in(path, std::ios::binary);
  ASSERT_TRUE(in) << "cannot read " << path;
  std::ostringstream text;
  text << in.rdbuf();
  std::string written;
  try {
    written = pf::table_in(text.str());
  } catch (const std::runtime_error& e) {
    FAIL() << path << ": " << e.what();
  }
  EXPECT_EQ(written, measured) << path << " does not hold the table measured now; regenerate it with\n  "
                               << pf::regenerate_command << "\nand review the diff (the prose may need updating).";
}

// The document's table is replaced between its markers and nowhere else.
TEST(analysis_table, markers) {
  const std::string doc = std::string("intro\n") + pf::table_begin + "old\n" + pf::table_end + "outro\n";
  EXPECT_EQ(pf::table_in(doc), "old\n");
  EXPECT_EQ(pf::with_table(doc, "| new |\n"),
            std::string("intro\n") + pf::table_begin + "| new |\n" + pf::table_end + "outro\n");
  EXPECT_THROW((void)pf::table_in("intro\n"), std::runtime_error);
  EXPECT_THROW((void)pf::table_in(std::string(pf::table_begin) + "no end\n"), std::runtime_error);
}
