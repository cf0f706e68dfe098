// The engine team's CSS easing in float, as game and UI engines write it: cubic-bezier(x1, y1, x2, y2)
// at time t solves x(u) = t by Newton's method from u = t (bisection when Newton stalls), then
// returns y(u). With OWN_BUG it returns y(t), skipping the inversion: the classic port that
// treats the Bezier's parameter as time.
#pragma once

#include <cmath>

namespace own {

struct css_easing {
  float x1, y1, x2, y2;

  // The cubic with end points 0 and 1 and control values a, b, in power form.
  static float bezier(float a, float b, float u) {
    const float c = 3 * a, bb = 3 * (b - a) - c, aa = 1 - c - bb;
    return ((aa * u + bb) * u + c) * u;
  }
  static float slope(float a, float b, float u) {
    const float c = 3 * a, bb = 3 * (b - a) - c, aa = 1 - c - bb;
    return (3 * aa * u + 2 * bb) * u + c;
  }

  float operator()(float t) const {
    if (t <= 0) return 0;
    if (t >= 1) return 1;
#ifdef OWN_BUG
    return bezier(y1, y2, t);
#else
    float u = t;
    for (int i = 0; i < 8; ++i) {
      const float x = bezier(x1, x2, u) - t;
      if (std::abs(x) < 1e-7f) return bezier(y1, y2, u);
      const float d = slope(x1, x2, u);
      if (std::abs(d) < 1e-6f) break;
      u -= x / d;
    }
    float lo = 0, hi = 1;  // Newton stalled or left [0, 1]: bisection (x is increasing)
    u = t;
    for (int i = 0; i < 40 && lo < hi; ++i) {
      const float x = bezier(x1, x2, u);
      if (x == t) break;
      (x < t ? lo : hi) = u;
      u = lo + (hi - lo) / 2;
    }
    return bezier(y1, y2, u);
#endif
  }
};

}  // namespace own
